// The periodic steady state of a linear model under loads of period T, found directly rather
// than by waiting for a transient to die out (which an undamped model never does): the state
// x = (u, v) of the free dofs from which one period of the time integration returns to x.
//
// One period of Newmark's average acceleration rule maps a start state x0 to
//   x(T) = Phi x0 + x_f,
// Phi (the monodromy matrix) the period map of the unloaded model and x_f the state after T
// from rest under the loads; column j of Phi is the state after T from a unit displacement or
// velocity of one free dof, less x_f. The periodic start is the fixed point (I - Phi) x0 = x_f ("shooting";
// e.g. Nayfeh & Balachandran, Applied Nonlinear Dynamics, 1995, section 7.3). The scheme's
// state is (u, v) alone, its acceleration following from the equation of motion, so a run
// started from x0 repeats itself every period to round-off.
//
// I - Phi is singular when a free vibration completes a whole number of cycles in T (an
// undamped model with a natural frequency k = n 2 pi / T: resonance), and then no periodic
// state exists. Near it the computed state is also unreliable: Newmark's period error moves the
// discrete resonance off the exact one by about k T (k dt)^2 / 12 (rad per period), so an
// amplitude whose distance from resonance is comparable to that error is mostly that error.
// periodicStart refuses both instead of returning an enormous amplitude. The distance is read
// from the multipliers, not from a condition number of I - Phi: near resonance I - Phi is a
// small multiple of a rotation, perfectly conditioned (its rcond stays near 1) however small.
#pragma once

#include <vector>

#include "fem/model/Model.hpp"
#include "fem/transient/Transient.hpp"

namespace beamrotor {

struct PeriodicStart {
  NodalField displacement, velocity;  ///< per node (m, rad; m/s, rad/s), as TransientOptions'
  /// Reciprocal condition number of I - Phi (1-norm estimate of the LU) with velocities scaled
  /// by T / (2 pi): how well the fixed-point solve is conditioned. It does not measure the
  /// nearness to resonance (see above).
  double rcond = 0;
  /// The eigenvalues' largest modulus of Phi (Floquet multipliers; 1 for an undamped model,
  /// below 1 with damping).
  double largestMultiplier = 0;
  /// Nearness to resonance: over the free vibrations of the model, the smallest |1 - mu| of
  /// their one-period multipliers mu, both Newmark's (mu = s^steps, s the one-step multiplier)
  /// and the exact one (angle k T, k the frequency Newmark's s stands for). For an undamped
  /// mode it is the angle (rad) by which k T misses a multiple of 2 pi; damping keeps it at
  /// least 1 - |mu|. Infinite for a model without free dofs.
  double resonanceDistance = 0;
  /// Newmark's period error (rad per period, |steps arg s - k T|) of the mode nearest
  /// resonance: the amplitude there is off by about periodError / resonanceDistance.
  double periodError = 0;
  /// That mode's frequency k (rad/s) and the multiple n of 2 pi / T nearest to k.
  double nearestFrequency = 0;
  int nearestHarmonic = 0;
};

/// Nearer to resonance than this (|1 - mu|) the fixed point is refused outright: its
/// round-off eps / distance would exceed sqrt(eps), half the digits.
inline constexpr double kPeriodicMinDistance = 1.5e-8;

/// Nearer than this many times Newmark's own period error the amplitude is refused too: its
/// error, about periodError / resonanceDistance, would exceed 1 / kPeriodicErrorMargin.
inline constexpr double kPeriodicErrorMargin = 2;

/// The periodic start of `options` (scheme newmark; its loads, model loads and support motions
/// of period `period` s; its time step dividing the period into whole steps) for the model
/// without its stops. Runs 2 n + 1 periods of solveTransient, n the free dofs: meant for small
/// models. Throws std::invalid_argument for another scheme or a step that does not divide the
/// period, and SolveError naming the resonance when resonanceDistance is below
/// kPeriodicMinDistance or below kPeriodicErrorMargin times periodError.
PeriodicStart periodicStart(const Model& model, const TransientOptions& options, double period);

}  // namespace beamrotor

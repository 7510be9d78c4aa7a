// Transient analysis: the free dofs of M a + C v + K u = f(t) stepped in time from an initial
// state, supports fixed at their prescribed values or moving as given functions of time.
//
// Schemes:
//  - newmark: Newmark's average acceleration rule, gamma = 1/2, beta = 1/4 (Newmark 1959),
//    unconditionally stable, no numerical damping, period error O(dt^2);
//  - hht: the Hilber-Hughes-Taylor alpha method (Hilber, Hughes and Taylor 1977), alpha in
//    [-1/3, 0], gamma = (1 - 2 alpha) / 2, beta = (1 - alpha)^2 / 4: unconditionally stable and
//    second order, damping the modes with omega dt >> 1 (spectral radius (1 + alpha) / (1 -
//    alpha) as omega dt -> infinity) while barely touching the well-resolved ones;
//  - centralDifference: explicit, lumped (diagonal) mass and diagonal damping, stable for
//    dt < 2 / omega_max; a larger step is run but warned about.
// The implicit schemes factorise their effective matrix once (UMFPACK) for the whole run.
#pragma once

#include <vector>

#include "fem/model/Model.hpp"
#include "fem/transient/TimeLoad.hpp"
#include "fem/transient/TransientResults.hpp"

namespace beamrotor {

enum class TimeScheme { newmark, hht, centralDifference };

/// A support dof moving in time. The dof must be held by one of the model's supports; its
/// value replaces the support's constant one. Displacement, velocity and acceleration are all
/// required (m, m/s, m/s^2 or rad, rad/s, rad/s^2) and must be consistent.
struct SupportMotion {
  int node = -1;
  Dof dof = Dof::uy;
  TimeFunction displacement, velocity, acceleration;
};

/// u(t) = amplitude sin(omega t + phase) with its two derivatives.
SupportMotion harmonicSupportMotion(int node, Dof dof, double amplitude, double omega,
                                    double phase = 0);

struct TransientOptions {
  TimeScheme scheme = TimeScheme::newmark;
  double timeStep = 0;  ///< s, constant
  /// s; the run takes round(endTime / timeStep) steps and ends at steps * timeStep.
  double endTime = 0;
  double hhtAlpha = -0.1;  ///< hht only, in [-1/3, 0]; 0 is the average acceleration rule

  /// Rayleigh damping added to the elements' dampers: C += rayleighMass M + rayleighStiffness K
  /// (1/s and s); modal damping ratio zeta = rayleighMass / (2 omega) + rayleighStiffness omega
  /// / 2.
  double rayleighMass = 0;
  double rayleighStiffness = 0;

  /// Loads varying in time, added to the model's own loads.
  std::vector<TimeLoad> loads;
  /// Factor of time on the model's own loads (nodal loads, distributed loads, self-weight);
  /// empty means 1 at all times (constant loads, e.g. a preload).
  TimeFunction modelLoadFactor;
  std::vector<SupportMotion> supportMotions;

  /// Initial state (m, rad; m/s, rad/s), per node as NodalField (a mode shape fits); empty
  /// means zero. Values at constrained dofs are ignored. The initial acceleration follows
  /// from the equation of motion at t = 0.
  NodalField initialDisplacement, initialVelocity;

  std::vector<NodeDof> histories;  ///< dofs whose displacement/velocity/acceleration to record
  int sampleEvery = 1;             ///< record histories and energy every n steps (and the last)
  int maxFrames = 0;               ///< full-field frames stored, evenly spaced; 0 for none
  bool energy = true;              ///< keep the energy account (a few sparse products a step)
  /// The model's contact constraints act as stops with this coefficient of restitution
  /// (0 plastic .. 1 elastic), see TransientStops; an impact's energy loss shows in the
  /// energy balance.
  double restitution = 0;
  /// false: the contacts are left out and the model is the linear one (the period map of
  /// PeriodicSteadyState needs it).
  bool stops = true;
};

/// Runs the analysis. Throws std::invalid_argument for bad options (non-positive step, alpha
/// outside [-1/3, 0], a load or history on a dof no element carries, a stop TransientStops
/// refuses), and SolveError for a singular effective or mass
/// matrix, or a mass matrix central difference cannot use.
TransientResult solveTransient(const Model& model, const TransientOptions& options);

/// Central-difference stability limit of a model with lumped mass (supports fixed). Throws
/// SolveError when the mass matrix is not diagonal or a free dof has no mass.
StabilityLimit centralDifferenceLimit(const Model& model);

}  // namespace beamrotor

// The torque a crankshaft needs to drive its crank-slider mechanisms at a uniform speed, and
// its harmonics: what a crank-driven pump puts into its drive train as torsional excitation.
// By the balance of power at uniform omega, each crank needs T omega = what its slider and rod
// take: the reciprocating mass m_rec a v, the rod's residual inertia couple J_res beta''
// beta', and a plunger pushing against a delivery pressure p on its delivery stroke, p A |v|
// while the slider moves away from the crank axis (v < 0 in the conventions of
// CrankSlider.hpp; suction taken at zero pressure). The rotating masses turn uniformly and need
// none. Over a revolution the inertia terms average to zero (they store and return kinetic
// energy), and the plunger's mean is p A 2 r / (2 pi) per crank: the pump's work p A 2r per
// stroke (the crank-slider dynamics of e.g. Shigley & Uicker, "Theory of Machines and
// Mechanisms", on the crank torque of a multi-cylinder machine).
#pragma once

#include <vector>

#include "problems/scenes/CrankSlider.hpp"

namespace beamrotor::crank {

/// What loads the cranks: the reduced reciprocating mass (kg), the rod's residual inertia
/// (kg m^2) and the plunger force on the delivery stroke p A (N); any may be 0.
struct CrankLoads {
  double reciprocatingMass = 0;
  double rodResidualInertia = 0;
  double plungerForce = 0;
};

/// The torque (N m) the crankshaft needs at crank angle phi (rad) turning at omega (rad/s),
/// summed over cranks set `phases` (rad) ahead of the first.
double crankTorque(const Geometry& g, const CrankLoads& loads, const std::vector<double>& phases,
                   double phi, double omega);

/// A harmonic of the crank torque: T(phi) = mean + sum amplitude cos(order phi + phase).
struct TorqueHarmonic {
  int order = 0;
  double amplitude = 0;  ///< N m
  double phase = 0;      ///< rad
};

struct TorqueSeries {
  double mean = 0;  ///< N m
  std::vector<TorqueHarmonic> harmonics;  ///< orders 1 .. orders
};

/// The mean and orders 1 .. `orders` of crankTorque over one revolution, by the trapezoidal
/// rule on 2^14 samples (the plunger's torque has a kink at the dead centres, so the rule
/// converges as 1 / samples^2: below 1e-7 of the amplitude).
TorqueSeries crankTorqueSeries(const Geometry& g, const CrankLoads& loads,
                               const std::vector<double>& phases, double omega, int orders);

}  // namespace beamrotor::crank

#include "problems/scenes/CrankTorque.hpp"

#include <cmath>
#include <numbers>

namespace beamrotor::crank {

double crankTorque(const Geometry& g, const CrankLoads& loads, const std::vector<double>& phases,
                   double phi, double omega) {
  double power = 0;
  for (double phase : phases) {
    const State s = exact(g, phi + phase, omega);
    power += loads.reciprocatingMass * s.a * s.v;
    power += loads.rodResidualInertia * s.betaDDot * s.betaDot;
    if (s.v < 0) power += loads.plungerForce * -s.v;
  }
  return power / omega;
}

TorqueSeries crankTorqueSeries(const Geometry& g, const CrankLoads& loads,
                               const std::vector<double>& phases, double omega, int orders) {
  constexpr int kSamples = 1 << 14;
  std::vector<double> cosSum(orders + 1, 0.0), sinSum(orders + 1, 0.0);
  for (int i = 0; i < kSamples; ++i) {
    const double phi = 2 * std::numbers::pi * i / kSamples;
    const double T = crankTorque(g, loads, phases, phi, omega);
    for (int k = 0; k <= orders; ++k) {
      cosSum[k] += T * std::cos(k * phi);
      sinSum[k] += T * std::sin(k * phi);
    }
  }
  TorqueSeries out;
  out.mean = cosSum[0] / kSamples;
  for (int k = 1; k <= orders; ++k) {
    // a cos + b sin = A cos(k phi + psi) with A = hypot(a, b), psi = atan2(-b, a).
    const double a = 2 * cosSum[k] / kSamples, b = 2 * sinSum[k] / kSamples;
    out.harmonics.push_back({k, std::hypot(a, b), std::atan2(-b, a)});
  }
  return out;
}

}  // namespace beamrotor::crank

#include "problems/verify/ShearLocking.hpp"

#include <cmath>

#include "fem/static/Static.hpp"
#include "problems/verify/VerifyModels.hpp"

namespace beamrotor::verify {

namespace {

constexpr double kLockingBeamLength = 1.0, kLockingTipForce = -1000.0;  // m, N

/// Relative error of the tip deflection of a cantilever of slenderness L/h with n elements.
double tipError(double slenderness, int n, BeamTheory theory) {
  const double h = kLockingBeamLength / slenderness;
  const auto section = steelRectangle(h, h);
  Model model;
  const Line line = planarBeam(model, kLockingBeamLength, section, n, {theory});
  model.addLoad({line.nodes.back(), Dof::uy, kLockingTipForce});
  StaticOptions options;
  options.singularRcond = 0;  // a slender locked beam is badly conditioned; show it anyway
  const double tip = solveStatic(model, options).displacement(line.nodes.back(), 1);
  // Timoshenko beam theory, bending plus shear: P L^3 / (3 E I) + P L / (kappa G A)
  // (Timoshenko and Gere, Mechanics of Materials; Cowper 1966 for kappa).
  const double exact =
      kLockingTipForce * std::pow(kLockingBeamLength, 3) / (3 * section->EIz()) +
      kLockingTipForce * kLockingBeamLength / (section->kappaY * section->material.G * section->A);
  return std::abs(tip - exact) / std::abs(exact);
}

LockingPoint point(double slenderness, int n) {
  return {slenderness, n, tipError(slenderness, n, BeamTheory::timoshenkoLinearFullIntegration),
          tipError(slenderness, n, BeamTheory::timoshenkoLinearReducedIntegration),
          tipError(slenderness, n, BeamTheory::timoshenko)};
}

}  // namespace

std::vector<LockingPoint> lockingAgainstSlenderness(const std::vector<double>& slenderness,
                                                    int elements) {
  std::vector<LockingPoint> points;
  for (double s : slenderness) points.push_back(point(s, elements));
  return points;
}

std::vector<LockingPoint> lockingAgainstElements(double slenderness,
                                                 const std::vector<int>& elementCounts) {
  std::vector<LockingPoint> points;
  for (int n : elementCounts) points.push_back(point(slenderness, n));
  return points;
}

}  // namespace beamrotor::verify

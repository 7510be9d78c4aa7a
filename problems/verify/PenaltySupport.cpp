#include "problems/verify/PenaltySupport.hpp"

#include <cmath>

#include "elements/Spring.hpp"
#include "fem/static/Static.hpp"
#include "problems/verify/VerifyModels.hpp"

namespace beamrotor::verify {

namespace {

constexpr double kJointBeamLength = 2.0, kJointTipForce = -1000.0;  // m, N
constexpr int kElements = 20;

/// Solves the tip-loaded cantilever, joined at midspan by springs of k = ratio E I / L^3, or as
/// one line when ratio is 0.
PenaltyPoint solveJoint(double ratio) {
  Model model;
  const auto section = steelRectangle(0.05, 0.05);
  const double EI = section->EIz(), k = ratio * EI / std::pow(kJointBeamLength, 3);
  int tip = -1;
  if (ratio > 0) {
    const Line first = planarBeam(model, kJointBeamLength / 2, section, kElements / 2);
    LineSpec spec;
    spec.start = Eigen::Vector3d(kJointBeamLength / 2, 0, 0);
    spec.segments.push_back({kJointBeamLength / 2, section, kElements / 2, 0, {}});
    const Line second = buildLine(model, spec);
    const int a = first.nodes.back(), b = second.nodes.front();
    model.add<Spring>(NodeDof{a, Dof::ux}, NodeDof{b, Dof::ux}, k);
    model.add<Spring>(NodeDof{a, Dof::uy}, NodeDof{b, Dof::uy}, k);
    model.add<Spring>(NodeDof{a, Dof::rz}, NodeDof{b, Dof::rz},
                      k * kJointBeamLength * kJointBeamLength);
    tip = second.nodes.back();
  } else {
    tip = planarBeam(model, kJointBeamLength, section, kElements).nodes.back();
  }
  model.addLoad({tip, Dof::uy, kJointTipForce});
  StaticOptions options;
  options.singularRcond = 0;  // the study wants the round-off, not a refusal
  const StaticResult r = solveStatic(model, options);
  // Hermite elements are exact for the end-loaded cantilever, P L^3 / (3 E I) (Timoshenko and
  // Gere). The joint adds P / k (shear spring) and, the midspan moment P L / 2 turning the
  // rotational spring by P / (2 k L), (L / 2) P / (2 k L) = P / (4 k): 1.25 P / k in all, that
  // is 3.75 / ratio relative.
  const double exact = kJointTipForce * std::pow(kJointBeamLength, 3) / (3 * EI);
  return {ratio, std::abs(r.displacement(tip, 1) - exact) / std::abs(exact),
          ratio > 0 ? 3.75 / ratio : 0, r.rcond};
}

}  // namespace

std::vector<PenaltyPoint> penaltyStudy(const std::vector<double>& stiffnessRatios) {
  std::vector<PenaltyPoint> points;
  for (double ratio : stiffnessRatios) points.push_back(solveJoint(ratio));
  return points;
}

PenaltyPoint eliminatedJoint() {
  return solveJoint(0);
}

}  // namespace beamrotor::verify

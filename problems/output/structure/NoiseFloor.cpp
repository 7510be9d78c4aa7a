#include "problems/output/structure/NoiseFloor.hpp"

#include <algorithm>
#include <cmath>

namespace beamrotor {

double NoiseFloor::motion(double value, Dof d) const {
  return std::abs(value) <= (isRotation(d) ? rotation : translation) ? 0.0 : value;
}

double NoiseFloor::load(double value, bool isMoment) const {
  return std::abs(value) <= (isMoment ? moment : force) ? 0.0 : value;
}

namespace {

/// The largest magnitudes of forces and of moments among `components`.
void takeLargest(const std::vector<ReactionComponent>& components, double& force,
                 double& moment) {
  for (const ReactionComponent& c : components)
    (isRotation(c.dof) ? moment : force) = std::max(isRotation(c.dof) ? moment : force,
                                                    std::abs(c.value));
}

/// The floors of the scales `translation` (m), `rotation` (rad), `force` (N) and `moment`
/// (N m) of a solution of `model` whose solve measured `roundOff`.
NoiseFloor floorOfScales(const Model& model, double roundOff, double translation,
                         double rotation, double force, double moment) {
  const double size = model.size();
  const double share = std::max(roundOff, kNegligibleShare);
  NoiseFloor floor;
  floor.translation = share * translation;
  floor.rotation = share * (size > 0 ? std::max(rotation, translation / size) : rotation);
  floor.force = share * force;
  floor.moment = share * std::max(moment, force * size);
  return floor;
}

/// The largest magnitudes of forces and of moments among enveloped `components`.
void takeLargest(const std::vector<std::pair<ReactionComponent, GovernedRange>>& components,
                 double& force, double& moment) {
  for (const auto& [c, range] : components) {
    double& largest = isRotation(c.dof) ? moment : force;
    largest = std::max({largest, std::abs(range.max.value), std::abs(range.min.value)});
  }
}

}  // namespace

NoiseFloor noiseFloorOf(const Model& model, const StaticResult& r,
                        const StaticExtremes* extremes) {
  double translation = 0, rotation = 0;
  for (Eigen::Index i = 0; i < r.displacement.rows(); ++i) {
    translation = std::max(translation, r.displacement.row(i).head<3>().norm());
    rotation = std::max(rotation, r.displacement.row(i).tail<3>().norm());
  }
  double force = 0, moment = 0, stress = 0;
  takeLargest(r.reactions, force, moment);
  takeLargest(r.elementForces, force, moment);
  if (extremes) {
    for (const ElementPeaks& p : extremes->peaks)
      stress = std::max({stress, std::abs(p.stress.value), std::abs(p.shear.value)});
    for (const auto& member : extremes->ranges)
      for (std::size_t k = 0; k < member.size(); ++k) {
        double& largest = isMomentComponent(kForceComponents[k]) ? moment : force;
        largest = std::max({largest, std::abs(member[k].max.value), std::abs(member[k].min.value)});
      }
  }
  NoiseFloor floor = floorOfScales(model, r.roundOff, translation, rotation, force, moment);
  floor.stress = std::max(r.roundOff, kNegligibleShare) * stress;
  return floor;
}

NoiseFloor noiseFloorOf(const Model& model, const CaseEnvelope& envelope, double roundOff) {
  double force = 0, moment = 0;
  takeLargest(envelope.reactions, force, moment);
  takeLargest(envelope.springs, force, moment);
  for (const auto& member : envelope.members)
    for (std::size_t k = 0; k < member.size(); ++k) {
      double& largest = isMomentComponent(kForceComponents[k]) ? moment : force;
      largest = std::max({largest, std::abs(member[k].max.value), std::abs(member[k].min.value)});
    }
  return floorOfScales(model, roundOff, std::abs(envelope.largestDisplacement.value), 0, force,
                       moment);
}

}  // namespace beamrotor

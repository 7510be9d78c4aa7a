#include "problems/output/structure/NoiseFloor.hpp"

#include <algorithm>
#include <cmath>

namespace beamrotor {

double NoiseFloor::motion(double value, Dof d) const {
  return zeroAtOrBelow(value, isRotation(d) ? rotation : translation);
}

double NoiseFloor::load(double value, bool isMoment) const {
  return zeroAtOrBelow(value, isMoment ? moment : force);
}

namespace {

/// The largest magnitudes of forces (N) and of moments (N m) taken so far.
struct LargestLoads {
  double force = 0, moment = 0;
  void take(double value, bool isMoment) {
    double& largest = isMoment ? moment : force;
    largest = std::max(largest, std::abs(value));
  }
  /// Both ends of an enveloped or ranged value.
  void take(double max, double min, bool isMoment) {
    take(max, isMoment);
    take(min, isMoment);
  }
};

/// The floors of the scales `translation` (m), `rotation` (rad) and `loads` of a solution of
/// `model` whose solve measured `roundOff`.
NoiseFloor floorOfScales(const Model& model, double roundOff, double translation,
                         double rotation, const LargestLoads& loads) {
  const double size = model.size();
  const double share = std::max(roundOff, kNegligibleShare);
  NoiseFloor floor;
  floor.translation = share * translation;
  floor.rotation = share * (size > 0 ? std::max(rotation, translation / size) : rotation);
  floor.force = share * loads.force;
  floor.moment = share * std::max(loads.moment, loads.force * size);
  return floor;
}

}  // namespace

NoiseFloor noiseFloorOf(const Model& model, const StaticResult& r,
                        const StaticExtremes* extremes) {
  double translation = 0, rotation = 0;
  for (Eigen::Index i = 0; i < r.displacement.rows(); ++i) {
    translation = std::max(translation, r.displacement.row(i).head<3>().norm());
    rotation = std::max(rotation, r.displacement.row(i).tail<3>().norm());
  }
  LargestLoads loads;
  for (const auto* list : {&r.reactions, &r.elementForces})
    for (const ReactionComponent& c : *list) loads.take(c.value, isRotation(c.dof));
  double stress = 0;
  if (extremes) {
    for (const ElementPeaks& p : extremes->peaks)
      stress = std::max({stress, std::abs(p.stress.value), std::abs(p.shear.value)});
    // Members' ranges with or without their places (RangesKept).
    for (std::size_t m = 0; m < rangedMembers(*extremes); ++m)
      for (std::size_t k = 0; k < kForceComponents.size(); ++k) {
        const RangeValues v = rangeValuesOf(*extremes, m, k);
        loads.take(v.max, v.min, isMomentComponent(kForceComponents[k]));
      }
  }
  NoiseFloor floor = floorOfScales(model, r.roundOff, translation, rotation, loads);
  floor.stress = std::max(r.roundOff, kNegligibleShare) * stress;
  return floor;
}

NoiseFloor noiseFloorOf(const Model& model, const CaseEnvelope& envelope, double roundOff) {
  LargestLoads loads;
  for (const auto* list : {&envelope.reactions, &envelope.springs})
    for (const auto& [c, range] : *list)
      loads.take(range.max.value, range.min.value, isRotation(c.dof));
  for (const auto& member : envelope.members)
    for (std::size_t k = 0; k < member.size(); ++k)
      loads.take(member[k].max.value, member[k].min.value, isMomentComponent(kForceComponents[k]));
  return floorOfScales(model, roundOff, std::abs(envelope.largestDisplacement.value), 0, loads);
}

}  // namespace beamrotor

#include "problems/cli/MemberSummary.hpp"

#include <algorithm>
#include <cmath>
#include <numeric>
#include <string>
#include <vector>

#include "problems/cli/Summary.hpp"

namespace beamrotor::cli {

namespace {

/// The larger in magnitude of a range's two ends.
const MemberValue& largerEnd(const ComponentRange& r) {
  return std::abs(r.max.value) >= std::abs(r.min.value) ? r.max : r.min;
}

}  // namespace

void printMemberExtremes(std::ostream& out, const Deck& deck, const Model& model,
                         const StaticExtremes& extremes, const NoiseFloor& floor,
                         const std::string& indent, const OutputUnits& units) {
  const OutputUnits::Shown length = units.valueIn("m", {1, "m"});
  const OutputUnits::Shown force = units.valueIn("N", {1, "N"});
  const OutputUnits::Shown moment = units.valueIn("N m", {1, "N m"});
  if (model.members().empty()) return;
  // The components a planar frame carries: N, Vy, Mz; a 3d one all six.
  const std::vector<ForceComponent> shown =
      deck.dimension == "planar"
          ? std::vector<ForceComponent>{ForceComponent::N, ForceComponent::Vy, ForceComponent::Mz}
          : std::vector<ForceComponent>(kForceComponents.begin(), kForceComponents.end());
  const MemberValue& top = extremes.largestDisplacement;
  const Eigen::Vector3d& at = top.x;
  out << indent << "largest displacement " << valueText(top.value, "m", units) << " at ("
      << formatValue(at.x() * length.factor) << ", " << formatValue(at.y() * length.factor) << ", "
      << formatValue(at.z() * length.factor) << ") " << length.unit << "\n";

  // Every member, or the kSummaryMembers of the largest bending moment, in the model's order.
  const auto& members = model.members();
  std::vector<std::size_t> listed(members.size());
  std::iota(listed.begin(), listed.end(), std::size_t{0});
  if (listed.size() > kSummaryMembers) {
    const auto moment = [&](std::size_t m) {
      return std::max(std::abs(largerEnd(extremes.ranges[m][int(ForceComponent::Mz)]).value),
                      std::abs(largerEnd(extremes.ranges[m][int(ForceComponent::My)]).value));
    };
    std::stable_sort(listed.begin(), listed.end(),
                     [&](std::size_t a, std::size_t b) { return moment(a) > moment(b); });
    listed.resize(kSummaryMembers);
    std::sort(listed.begin(), listed.end());
  }
  out << indent << "members (largest |value| in member axes, at " << length.unit
      << " from the member's start; " << force.unit << ", " << moment.unit << ", " << length.unit
      << ")";
  if (listed.size() < members.size())
    out << ", the " << listed.size() << " of the largest bending moment among "
        << members.size() << " (all in results.json)";
  out << ":\n";
  for (std::size_t m : listed) {
    out << indent << "  " << padded(members[m].first, 12);
    for (ForceComponent c : shown) {
      const MemberValue& v = largerEnd(extremes.ranges[m][int(c)]);
      // A resultant that is zero (or round-off) all along has no place worth naming.
      const double value = floor.load(v.value, isMomentComponent(c));
      std::string text = componentName(c);
      text += " ";
      text += formatValue(value * (isMomentComponent(c) ? moment : force).factor);
      if (value != 0) {
        text += " @ ";
        text += formatValue(v.along * length.factor);
      }
      out << padded(text, 26);
    }
    out << "deflection "
        << formatValue(floor.motion(extremes.chordDeflections[m].value, Dof::ux) * length.factor)
        << "\n";
  }
}

}  // namespace beamrotor::cli

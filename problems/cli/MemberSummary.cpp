#include "problems/cli/MemberSummary.hpp"

#include <algorithm>
#include <cmath>
#include <string>

#include "fem/assembly/MemberExtrema.hpp"
#include "problems/cli/Summary.hpp"

namespace beamrotor::cli {

void printMemberExtremes(std::ostream& out, const Deck& deck, const Model& model,
                         const StaticResult& statics) {
  if (model.members().empty()) return;
  // The components a planar frame carries: N, Vy, Mz; a 3d one all six.
  const std::vector<ForceComponent> shown =
      deck.dimension == "planar"
          ? std::vector<ForceComponent>{ForceComponent::N, ForceComponent::Vy, ForceComponent::Mz}
          : std::vector<ForceComponent>(kForceComponents.begin(), kForceComponents.end());
  const MemberValue top = largestDisplacement({model, statics.displacement});
  const Eigen::Vector3d& at = top.x;
  out << "  largest displacement " << formatValue(top.value) << " m at (" << formatValue(at.x())
      << ", " << formatValue(at.y()) << ", " << formatValue(at.z()) << ") m\n";
  out << "  members (largest |value| in member axes, at m from the member's start; N, N m, m):\n";
  for (const auto& [name, elements] : model.members()) {
    const auto ranges = memberForceRanges({model, statics.displacement}, elements);
    out << "    " << padded(name, 12);
    for (ForceComponent c : shown) {
      const ComponentRange& r = ranges[int(c)];
      const MemberValue& top = std::abs(r.max.value) >= std::abs(r.min.value) ? r.max : r.min;
      out << padded(std::string(componentName(c)) + " " + formatValue(top.value) + " @ " +
                        formatValue(top.along),
                    26);
    }
    out << "deflection "
        << formatValue(largestChordDeflection({model, statics.displacement}, elements).value)
        << "\n";
  }
}

}  // namespace beamrotor::cli

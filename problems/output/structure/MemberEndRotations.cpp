// Member end rotations at hinged joints (see MemberEndRotations.hpp).
#include "problems/output/structure/MemberEndRotations.hpp"

#include "fem/model/LineElement.hpp"

namespace beamrotor {

std::map<int, std::vector<MemberEndRotation>> memberEndRotations(
    const LoadedSolution& solution, const std::vector<SideRotations>& hinges) {
  std::map<int, std::vector<MemberEndRotation>> out;
  for (const SideRotations& h : hinges) out[h.node];
  const Model& model = *solution.model;
  for (const auto& [name, elements] : model.members())
    for (std::size_t i = 0; i < elements.size(); ++i) {
      const LineElement* line = asLine(model.elements()[elements[i]]);
      if (!line) continue;
      for (int end : {0, 1}) {
        const auto at = out.find(line->endNodes()[end]);
        if (at == out.end()) continue;
        const bool memberStart = end == 0 && i == 0;
        const bool memberEnd = end == 1 && i + 1 == elements.size();
        std::string label = name;
        label += memberStart ? "_start" : memberEnd ? "_end" : end == 1 ? "_before" : "_after";
        const auto u = solution.displacementAt(elements[i], end);
        at->second.push_back({std::move(label), Eigen::Vector3d(u[3], u[4], u[5])});
      }
    }
  return out;
}

}  // namespace beamrotor

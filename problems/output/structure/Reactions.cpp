// Reactions grouped per support and component (see Reactions.hpp).
#include "problems/output/structure/Reactions.hpp"

#include <algorithm>

namespace beamrotor {

std::string_view reactionName(Dof d) {
  static constexpr std::string_view names[kDofKinds] = {"fx", "fy", "fz", "mx", "my", "mz"};
  return names[dofIndex(d)];
}

std::string_view reactionUnit(Dof d) {
  return isRotation(d) ? "N m" : "N";
}

std::vector<SupportReactions> reactionsBySupport(const StaticResult& result) {
  return forcesByName(result.reactions);
}

std::vector<SupportReactions> forcesByName(const std::vector<ReactionComponent>& forces) {
  std::vector<SupportReactions> grouped;
  for (const ReactionComponent& r : forces) {
    auto support = std::find_if(grouped.begin(), grouped.end(),
                                [&](const SupportReactions& s) { return s.support == r.support; });
    if (support == grouped.end()) support = grouped.insert(grouped.end(), {r.support, {}});
    auto component =
        std::find_if(support->components.begin(), support->components.end(),
                     [&](const std::pair<Dof, double>& c) { return c.first == r.dof; });
    if (component == support->components.end())
      support->components.emplace_back(r.dof, r.value);
    else
      component->second += r.value;
  }
  for (SupportReactions& s : grouped)
    std::sort(s.components.begin(), s.components.end(),
              [](const auto& a, const auto& b) { return dofIndex(a.first) < dofIndex(b.first); });
  return grouped;
}

}  // namespace beamrotor

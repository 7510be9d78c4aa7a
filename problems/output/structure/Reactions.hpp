// Support reactions grouped the way a reader looks for them: per named support, one value per
// component (fx fy fz in N, mx my mz in N m, global frame), as results.json, sweep.csv and the
// sweep charts report them.
#pragma once

#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include "fem/model/Results.hpp"

namespace beamrotor {

/// "fx", "fy", "fz", "mx", "my", "mz": the reaction conjugate to ux ... rz.
std::string_view reactionName(Dof d);
/// "N" for forces, "N m" for moments.
std::string_view reactionUnit(Dof d);

/// The reactions of one support: components in ux ... rz order, each the sum over the
/// support's constrained dofs of that kind (a support normally has one per kind).
struct SupportReactions {
  std::string support;
  std::vector<std::pair<Dof, double>> components;
};

/// Supports in the order they first appear in result.reactions (the model's support order).
std::vector<SupportReactions> reactionsBySupport(const StaticResult& result);
/// The same for any such forces, e.g. those of springs and bearings (elementForces).
std::vector<SupportReactions> forcesByName(const std::vector<ReactionComponent>& forces);

}  // namespace beamrotor

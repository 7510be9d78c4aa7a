// Tension-only and compression-only members (rods and cables that go slack, struts that lift
// off), solved by an active-set iteration like the contacts' (ActiveSet.hpp): solve with the
// slack members left out, take slack a member whose force has the wrong sign, take back a
// slack member whose ends move apart (tension-only) or together (compression-only), repeat
// until nothing changes. At a switch point the member's force and its elongation are both
// zero, so either choice gives the same solution: the switch is exact, not a soft spring.
#pragma once

#include <functional>
#include <memory>
#include <string>
#include <vector>

#include "fem/model/Model.hpp"
#include "fem/static/Static.hpp"

namespace beamrotor {

enum class MemberAction { both, tensionOnly, compressionOnly };

/// A named member of the model (Model::members, one line element) that acts one way only.
struct OneWayMember {
  std::string name;
  MemberAction acts = MemberAction::tensionOnly;
};

struct OneWaySolution {
  std::shared_ptr<const Model> model;      ///< built with the settled slack members
  StaticResult result;  ///< of that model, its oneWayMembers in the order given
  int iterations = 0;                      ///< static solves the member loop needed
};

/// Builds the model with the members flagged slack (one flag per entry of `members`) left
/// out or made slack (Beam::setSlack); every build numbers the nodes alike and names the
/// members that remain.
using OneWayModelBuilder =
    std::function<std::shared_ptr<const Model>(const std::vector<bool>& slack)>;

/// Solves the statics of build's model with `members` acting one way (contacts, if any, are
/// solved inside each static solve). Throws std::invalid_argument for a member that is not
/// a single line element of the full model, SolveError when the set does not settle, and as
/// solveStatic does (a structure that is a mechanism once a member goes slack).
OneWaySolution solveWithOneWayMembers(const OneWayModelBuilder& build,
                                      const std::vector<OneWayMember>& members,
                                      const StaticOptions& options = {});

}  // namespace beamrotor

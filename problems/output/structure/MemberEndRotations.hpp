// The rotation of each member end at a frame's hinged joints: where several members meet, "the
// beam end on the left" names none of them, so each end is reported by its member.
#pragma once

#include <map>
#include <string>
#include <vector>

#include "fem/assembly/Recovery.hpp"
#include "fem/model/Results.hpp"

namespace beamrotor {

/// One member end's rotation (global frame, rad) at a joint, labelled "<member>_start" or
/// "<member>_end", or "<member>_before" and "<member>_after" where the joint lies inside the
/// member (the element ends towards its `from` and its `to`).
struct MemberEndRotation {
  std::string label;
  Eigen::Vector3d rotation = Eigen::Vector3d::Zero();
};

/// For each node in `hinges` (a static solution's hinge rotations), the rotation of every
/// member end there, in the model's member order; one pass over the members.
std::map<int, std::vector<MemberEndRotation>> memberEndRotations(
    const LoadedSolution& solution, const std::vector<SideRotations>& hinges);

}  // namespace beamrotor

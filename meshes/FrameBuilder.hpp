// Builds a frame of straight members between named joints: each member is meshed like a
// segment of meshes/LineBuilder (element count or target size), cut at the stations named
// on it, and shares the joints' nodes with the members meeting there. Each member's local
// axes follow one convention (memberAxes) unless the member gives its own.
#pragma once

#include <array>
#include <optional>
#include <string>
#include <vector>

#include "meshes/LineBuilder.hpp"

namespace beamrotor {

/// A joint of the frame.
struct FrameJoint {
  std::string name;
  Eigen::Vector3d x = Eigen::Vector3d::Zero();  ///< m, global frame
  /// A joint inside a member (another member starts or ends there): that member's index and
  /// the fraction of its length at x; the member is cut there and shares the joint's node.
  int member = -1;
  double fraction = 0;
};

/// How a member's local y and z axes are chosen about its axis.
struct MemberOrientation {
  /// A global direction that lies in the member's local x-z plane (local z is its part
  /// perpendicular to the member), or nullopt for the default convention (memberAxes).
  std::optional<Eigen::Vector3d> zReference;
  /// A global direction in the local x-y plane instead (local y is its perpendicular part).
  std::optional<Eigen::Vector3d> yReference;
  /// Rotation (rad) of local y and z about local x, right-handed, after the above.
  double roll = 0;
};

/// A straight member from joint `from` to joint `to` (indices into FrameSpec::joints).
struct FrameMember {
  int from = -1, to = -1;
  Segment mesh;  ///< section, element count or size, options; length is the joints' distance
  MemberOrientation orientation;
  /// Released rotations (local axes rx, ry, rz) at the start (0) and the end (1).
  std::array<std::vector<Dof>, 2> releases;
};

/// A named station on a member at `fraction` of its length from its start joint.
struct MemberStation {
  std::string name;
  int member = -1;
  double fraction = 0;
};

struct FrameSpec {
  DofSet dofs = DofSet::planar();
  std::vector<FrameJoint> joints;
  std::vector<FrameMember> members;
  std::vector<MemberStation> stations;
};

/// What the builder made.
struct FrameMesh {
  std::vector<int> jointNodes;  ///< the model node of each joint
  /// Per member, its elements from start joint to end joint (owned by the model) and the
  /// fraction of the member's length at each of its nodes (elements + 1 values, 0 to 1).
  std::vector<std::vector<Beam*>> memberBeams;
  std::vector<std::vector<double>> memberFractions;
};

/// Rows: the local x, y, z axes of a member along `axis` (any length > 0). Default
/// convention: local z is the part of global +z perpendicular to the member (so in a planar
/// model, x-y plane, local z = +z and local y is local x turned 90 degrees counter-clockwise);
/// a member along global z has local y = global +y. Then the orientation's references and
/// roll. Throws std::invalid_argument when a reference is parallel to the member or zero.
Eigen::Matrix3d memberAxes(const Eigen::Vector3d& axis, const MemberOrientation& orientation);

/// Adds the frame's nodes and beams to model and names its joints and stations. Throws
/// std::invalid_argument for coincident joints, a member of zero length, a bad station.
FrameMesh buildFrame(Model& model, const FrameSpec& spec);

}  // namespace beamrotor

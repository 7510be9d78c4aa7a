// The frame part of a deck (see FORMAT.md, "Frames"): joints with coordinates and members
// between them. Each member's mesh, section and formulation are the deck segment of the same
// index (Deck::segments), so everything that refines or re-theorises segments (accuracy:,
// converge, --formulation) treats members alike. Plain values, read by ReadFrame.cpp and
// built by problems/run/ModelBuilder through meshes/FrameBuilder.
#pragma once

#include <array>
#include <string>
#include <vector>

#include "fem/static/OneWayMembers.hpp"
#include "meshes/FrameBuilder.hpp"
#include "problems/deck/parse/DeckError.hpp"

namespace beamrotor {

/// A joint: a named node at a place (planar decks give [x, y], z = 0).
struct DeckJoint {
  std::string name;
  Eigen::Vector3d x = Eigen::Vector3d::Zero();
  DeckPlace place;
  /// A joint a member starts or ends at on another member (`from: front@0.5`): that member
  /// (index into DeckFrame::members) and the fraction of its length; -1 for a node.
  int member = -1;
  double fraction = 0;
};

/// A member between two joints; its segment (same index) holds name, section and mesh.
struct DeckMember {
  int from = -1, to = -1;  ///< indices into DeckFrame::joints
  MemberOrientation orientation;
  std::array<std::vector<Dof>, 2> releases;  ///< local rotations released at start, end
  /// Tension-only or compression-only (`acts:`): slack members are found by the statics'
  /// active set (fem/static/OneWayMembers).
  MemberAction acts = MemberAction::both;
  DeckPlace place;
};

struct DeckFrame {
  std::vector<DeckJoint> joints;
  std::vector<DeckMember> members;
  std::vector<MemberStation> stations;  ///< named places along members (points: and at: maps)
  /// Whether some member acts one way only.
  bool hasOneWayMembers() const {
    for (const DeckMember& m : members)
      if (m.acts != MemberAction::both) return true;
    return false;
  }
};

}  // namespace beamrotor

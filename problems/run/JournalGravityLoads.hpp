// Plain journal bearings with `load: gravity`: their static load is the rotor's weight share,
// found from the rotor itself. The rotor (shaft, disks, masses) rests on pinned supports at
// every bearing under g = 9.81 m/s^2 along -y (fem/rotor/GravityLoads.hpp), and each such
// journal carries the upward force of its support. With two bearings this is exact (the loads
// are statically determinate); with three or more it is the share of a rigidly supported
// shaft, since a journal's stiffness itself depends on the load it is to share.
#pragma once

#include "problems/deck/Deck.hpp"

namespace beamrotor {

/// True when some plain journal of the deck still waits for its gravity load.
bool needsJournalLoads(const Deck& deck);

/// The deck with every such journal's load and coefficient table filled. Throws DeckError at
/// the bearing when its support pulls down instead of up (the rotor's weight lifts off it) or
/// its film at from_rpm is too thin for that load.
Deck withJournalLoads(const Deck& deck);

}  // namespace beamrotor

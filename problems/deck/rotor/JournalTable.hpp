// A plain journal bearing's coefficient table from its geometry, oil and load: the reader
// fills it for a load given as a number, the run for `load: gravity` once the rotor's weight
// share is known.
#pragma once

#include "problems/deck/rotor/DeckRotor.hpp"

namespace beamrotor {

/// Fills b.journalPoints and b.table at b.speeds for b.journal (set, with its load), by the
/// short-bearing theory or the finite film (b.journalModel). Throws std::invalid_argument, naming
/// the speed, when the film at the slowest speed would be thinner than 1 % of the clearance (the
/// journal touches the bearing).
void fillJournalTable(DeckBearing& b);

}  // namespace beamrotor

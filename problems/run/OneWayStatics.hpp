// A deck's tension-only and compression-only members (`acts:`): which of them are slack under
// the deck's loads, found before its analyses run, so that every output reads the model with
// those members out of action (fem/static/OneWayMembers).
#pragma once

#include <optional>

#include "fem/static/OneWayMembers.hpp"
#include "problems/deck/Deck.hpp"

namespace beamrotor {

/// The settled model and static solution of a deck with one-way members; nullopt for a deck
/// without. Throws DeckSolveError at the first one-way member when the loop fails (a
/// mechanism once a member is slack, a member split into several elements, no settling).
std::optional<OneWaySolution> solveOneWayMembers(const Deck& deck);

}  // namespace beamrotor

// Deck -> Model: the line of beams with its points, then supports, springs, masses, hinges
// and loads at those points. The deck is already validated; what the core still rejects is
// reported as a DeckError at the deck item that caused it.
#pragma once

#include <memory>

#include "fem/model/Model.hpp"
#include "problems/deck/Deck.hpp"

namespace beamrotor {

/// Builds the model a deck describes. Throws DeckError.
std::shared_ptr<Model> buildModel(const Deck& deck);

}  // namespace beamrotor

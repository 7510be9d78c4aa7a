// Deck -> Model: the line of beams with its points, then supports, springs, masses, hinges
// and loads at those points. The deck is already validated; what the core still rejects is
// reported as a DeckError at the deck item that caused it.
#pragma once

#include <memory>
#include <vector>

#include "fem/model/Loading.hpp"
#include "fem/model/Model.hpp"
#include "problems/deck/Deck.hpp"

namespace beamrotor {

/// Builds the model a deck describes, the frame members flagged in `slackMembers` (one flag
/// per member, or none) slack (Beam::setSlack). Throws DeckError.
std::shared_ptr<Model> buildModel(const Deck& deck, const std::vector<bool>& slackMembers = {});

/// `loads` (a load case's, in the syntax of `loads:`) on the model buildModel(deck) built: its
/// point loads at their nodes and each beam's span load, exactly as buildModel puts the deck's
/// own loads on its beams. Throws DeckError.
Loading loadingOf(const Deck& deck, const Model& model, const std::vector<DeckLoad>& loads);

}  // namespace beamrotor

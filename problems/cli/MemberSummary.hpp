// The summary's lines on a frame's members: per member the largest |value| of each resultant
// that is not zero everywhere (member axes), where along the member it lies, and the
// member's deflection from its chord.
#pragma once

#include <ostream>

#include "fem/model/Model.hpp"
#include "fem/model/Results.hpp"
#include "problems/deck/Deck.hpp"

namespace beamrotor::cli {

/// Nothing for a model without members (a line deck).
void printMemberExtremes(std::ostream& out, const Deck& deck, const Model& model,
                         const StaticResult& statics);

}  // namespace beamrotor::cli

// The beam theory given on the command line instead of in the deck:
//   --formulation timoshenko        every beam segment becomes a Timoshenko beam
//   --formulation euler-bernoulli   every beam segment becomes an Euler-Bernoulli beam
// and any other name a deck's `formulation:` accepts (Formulations.hpp, one list for both),
// so the same deck can be solved both ways and the shear deformation's effect read off.
#pragma once

#include <string>

#include "problems/deck/Deck.hpp"

namespace beamrotor {

/// Replaces the formulation of the deck's model and of every segment (a segment's own
/// `formulation:` included). Throws DeckError naming the deck and the option, with the names
/// allowed and the closest one, for a name that is not in kFormulations.
void applyFormulationOption(const std::string& theory, Deck& deck);

}  // namespace beamrotor

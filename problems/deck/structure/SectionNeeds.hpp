// A `general` section gives only what the deck writes; what a run needs from it and the deck
// left out is refused at the section's line, naming the key, instead of a default that would
// change the answer (an outer fibre guessed from I and A, a Timoshenko beam without shear
// flexibility, a frame without torsional stiffness).
#pragma once

#include "problems/deck/Deck.hpp"

namespace beamrotor {

/// Throws DeckError at the first segment's `general` section that lacks a value the deck's run
/// needs: `depth` when a static analysis recovers stresses (and `width` when the model also
/// bends about y, i.e. carries uz), `J` in a 3D model (torsion), `kappa` when the segment's
/// element is a Timoshenko one (from the deck, its segment or `--formulation`).
void requireSectionValues(const Deck& deck);

}  // namespace beamrotor

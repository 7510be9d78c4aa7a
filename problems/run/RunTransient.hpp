// Runs a deck's transient analysis: the deck's settings become TransientOptions, the core
// steps the model, and the deck's named histories (recorded dofs and values derived from them)
// are formed at the sample times.
#pragma once

#include "fem/model/Model.hpp"
#include "problems/deck/Deck.hpp"
#include "problems/run/TransientOutcome.hpp"

namespace beamrotor {

/// Solves transient run `t` of `deck` on `model`. Throws DeckError at the deck's dt when
/// the central-difference scheme is asked for a step above its stability limit 2 / omega_max
/// (a run that would only grow without bound), and what solveTransient throws otherwise.
TransientOutcome runTransient(const Deck& deck, const DeckTransient& t, const Model& model);

}  // namespace beamrotor

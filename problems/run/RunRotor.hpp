// Solving the rotor analyses of a deck (rotor, campbell, unbalance, rigid-body) with the
// core's fem/rotor/ functions and, for rigid-body, the forme-shaft scene's two-dof form.
#pragma once

#include "fem/model/Model.hpp"
#include "problems/deck/Deck.hpp"
#include "problems/run/RotorRunResult.hpp"

namespace beamrotor {

/// Solves one analysis with isRotorAnalysis(a.kind). Throws what the core throws
/// (SolveError, std::invalid_argument); the caller reports it at the analysis.
RotorOutcome solveRotorAnalysis(const Deck& deck, const DeckAnalysis& a, const Model& model);

}  // namespace beamrotor

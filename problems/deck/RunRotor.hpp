// Solving the rotor analyses of a deck (rotor, campbell, unbalance, rigid-body) with the
// core's fem/Rotor* functions and, for rigid-body, the forme-shaft scene's two-dof form.
#pragma once

#include "fem/Model.hpp"
#include "problems/RotorRunResult.hpp"
#include "problems/deck/Deck.hpp"

namespace beamrotor {

/// Solves one analysis with isRotorAnalysis(a.type). Throws what the core throws
/// (SolveError, std::invalid_argument); the caller reports it at the analysis.
RotorOutcome solveRotorAnalysis(const Deck& deck, const DeckAnalysis& a, const Model& model);

}  // namespace beamrotor

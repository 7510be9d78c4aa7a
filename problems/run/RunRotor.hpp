// Solving the rotor analyses of a deck (rotor, campbell, unbalance, rigid-body,
// frequency-response, critical-speed-map, bearing-loads) with the core's fem/rotor/ functions
// and, for rigid-body, the forme-shaft scene's two-dof form.
#pragma once

#include <string>
#include <vector>

#include "fem/model/Model.hpp"
#include "problems/deck/Deck.hpp"
#include "problems/run/RunResult.hpp"

namespace beamrotor {

/// Solves one analysis with isRotorAnalysis(a.kind), giving its kind's result (RotorResult).
/// Throws what the core throws (SolveError, std::invalid_argument); the caller reports it at
/// the analysis.
AnalysisResult solveRotorAnalysis(const Deck& deck, const DeckAnalysis& a, const Model& model);

/// The warnings of a rotor analysis' result (CampbellWarnings.hpp): a Campbell diagram's
/// tracking and onset, an unbalance analysis' onset; none for the other kinds.
std::vector<std::string> rotorWarnings(const AnalysisResult& result);

}  // namespace beamrotor

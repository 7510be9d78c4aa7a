// The value of a deck's check quantity in a solved analysis: the running side of the
// quantities the deck reader parses (problems/deck/Quantity.hpp).
#pragma once

#include "fem/assembly/Recovery.hpp"
#include "fem/model/Model.hpp"
#include "problems/deck/Quantity.hpp"
#include "problems/run/RunResult.hpp"

namespace beamrotor {

/// The quantity's value in a solved analysis of model. Throws std::invalid_argument when the
/// analysis lacks it (wrong type, too few modes, unknown name).
double measure(const Quantity& q, const AnalysisOutcome& outcome, const Model& model);

/// The same in a run's analysis: what checks and studies measure. A section quantity reads
/// the run's catalogue sections besides the model (MeasureSection.hpp).
double measure(const Quantity& q, const AnalysisOutcome& outcome, const RunResult& run);

/// A static quantity's value in static solution r, recovered as `solution` (r on its model,
/// under its loading: a load case's, or the model's own). Throws as measure does.
double measureStatic(const Quantity& q, const StaticResult& r, const LoadedSolution& solution);

}  // namespace beamrotor

// The lines `beamrotor solve` prints for transient analyses: the scheme and time grid, the
// largest value of each named history, impacts and warnings; and per swept value the maxima.
#pragma once

#include <ostream>

#include "problems/deck/OutputUnits.hpp"
#include "problems/run/RunResult.hpp"

namespace beamrotor::cli {

/// A transient analysis of one run.
void printTransient(std::ostream& out, const AnalysisOutcome& a, const OutputUnits& units = {});

/// One row per swept value with the maxima of the first transient analysis (nothing when the
/// runs have none).
void printTransientSweep(std::ostream& out, const SweepResult& sweep,
                         const OutputUnits& units = {});

}  // namespace beamrotor::cli

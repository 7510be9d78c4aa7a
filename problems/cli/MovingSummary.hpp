// The lines `beamrotor solve` prints for a moving-load analysis: the path and the train, then
// per quantity its largest and smallest value under the train with the first wheel's
// position that gives each.
#pragma once

#include <ostream>

#include "problems/deck/OutputUnits.hpp"
#include "problems/run/RunResult.hpp"

namespace beamrotor::cli {

/// The train, and each quantity's envelope with the governing positions, in `units`.
void printMovingLoad(std::ostream& out, const AnalysisOutcome& a, const MovingLoadOutcome& m,
                     const OutputUnits& units);

}  // namespace beamrotor::cli

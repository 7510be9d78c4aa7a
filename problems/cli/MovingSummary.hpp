// The lines `beamrotor solve` prints for a moving-load analysis: the path and the train, then
// per quantity its largest and smallest value under the train with the first wheel's
// position that gives each.
#pragma once

#include <ostream>

#include "problems/run/RunResult.hpp"

namespace beamrotor::cli {

void printMovingLoad(std::ostream& out, const AnalysisOutcome& a, const MovingLoadOutcome& m);

}  // namespace beamrotor::cli

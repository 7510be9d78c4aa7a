// The peaks a refined sweep (`sweep: refine:`) found, for the summary.
#pragma once

#include <ostream>

#include "problems/deck/OutputUnits.hpp"
#include "problems/run/Study.hpp"

namespace beamrotor::cli {

/// "peaks of Q (analysis A), bracketed to T of c: c = v1 (q1), ..." when the study is a sweep
/// its deck refines (nothing otherwise); read again from the deck file at deckPath. The swept
/// values in the user's `units` where they set their quantity.
void printSweepPeaks(std::ostream& out, const Study& study, const std::string& deckPath,
                     const OutputUnits& units = {});

}  // namespace beamrotor::cli

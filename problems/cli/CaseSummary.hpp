// The summary's lines on a static analysis' load cases and combinations: each case's and
// combination's reactions, point displacements, largest stresses and member extremes (one line
// each when there are more than kSummaryCases, MemberOutput.hpp), then the envelope over the combinations with
// the combination that governs each extreme.
#pragma once

#include <cstddef>
#include <ostream>

#include "problems/deck/Deck.hpp"
#include "problems/deck/OutputUnits.hpp"
#include "problems/output/structure/MemberOutput.hpp"
#include "problems/output/structure/StaticExtremes.hpp"
#include "problems/run/RunResult.hpp"

namespace beamrotor::cli {

/// Nothing for an analysis without load cases.
void printCases(std::ostream& out, const Deck& deck, const RunResult& run,
                const AnalysisOutcome& a, const AnalysisExtremes& extremes,
                const OutputUnits& units = {});

}  // namespace beamrotor::cli

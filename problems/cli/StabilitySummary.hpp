// The lines `beamrotor solve` prints for the analyses with geometric stiffness: a buckling
// analysis' load factors, and a second-order static analysis' critical factor and
// amplification against first order.
#pragma once

#include <ostream>

#include "problems/run/RunResult.hpp"

namespace beamrotor::cli {

/// A buckling analysis of one run.
void printBuckling(std::ostream& out, const AnalysisOutcome& a);

/// The second-order lines of a static analysis solved with `second_order: true` (nothing
/// otherwise).
void printSecondOrder(std::ostream& out, const AnalysisOutcome& a);

}  // namespace beamrotor::cli

// `beamrotor report`: the verification report (problems/verify/Report.hpp) from the command
// line.
#pragma once

#include <ostream>

#include "problems/verify/Report.hpp"

namespace beamrotor::cli {

/// `beamrotor report [--converge]`.
struct ReportRequest {
  verify::ReportOptions report;
  /// First run each deck's convergence study (its default quantity) into DIR/convergence/<deck>/;
  /// a deck with nothing to converge is skipped, and the page says so.
  bool converge = false;
};

/// Writes the report and prints where it is and how many checks pass; kSolveFailure when the
/// page cannot be written or a convergence study fails, kInputError for a deck it cannot read
/// (with --converge) or no decks, kOk otherwise (a failing check is in the page, not an error
/// here).
int reportCommand(const ReportRequest& request, std::ostream& out, std::ostream& err);

}  // namespace beamrotor::cli

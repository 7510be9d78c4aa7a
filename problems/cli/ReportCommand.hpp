// `beamrotor report`: the verification report (problems/verify/Report.hpp) from the command
// line.
#pragma once

#include <ostream>

#include "problems/verify/Report.hpp"

namespace beamrotor::cli {

/// Writes the report and prints where it is and how many checks pass; kSolveFailure when the
/// page cannot be written, kOk otherwise (a failing check is in the page, not an error here).
int reportCommand(const verify::ReportOptions& options, std::ostream& out, std::ostream& err);

}  // namespace beamrotor::cli

#include "problems/cli/ReportCommand.hpp"

#include "problems/cli/ExitCodes.hpp"
#include "problems/output/files/Gnuplot.hpp"

namespace beamrotor::cli {

int reportCommand(const verify::ReportOptions& options, std::ostream& out, std::ostream& err) {
  try {
    const verify::ReportSummary s = verify::writeReport(options, err);
    out << "checks: " << s.checks - s.failedChecks << " pass, " << s.failedChecks << " fail, "
        << s.notApplied << " did not apply";
    if (s.unsolvedDecks) out << ", " << s.unsolvedDecks << " deck(s) not solved";
    out << "\nreport: " << s.page.string() << "\n";
    return kOk;
  } catch (const std::invalid_argument& e) {
    err << "beamrotor report: " << e.what() << "\n";
    return kInputError;
  } catch (const std::exception& e) {
    err << "beamrotor report: " << e.what() << "\n";
    return kSolveFailure;
  }
}

}  // namespace beamrotor::cli

// `beamrotor report`: regenerates the verification report, DIR/index.html, from the shipped
// decks' checks, the convergence charts found in DIR/convergence/ and the failure-case
// studies (charts drawn into DIR/charts/).
#pragma once

#include <filesystem>
#include <ostream>

#include "problems/verify/FailureCharts.hpp"

namespace beamrotor::verify {

struct ReportOptions {
  std::filesystem::path outDir = "out/report";
  std::filesystem::path problemsDir = "problems";  ///< whose *.yaml decks are checked
  FailureChartOptions failures;
  /// Decks whose convergence study was skipped, with the reason (deck file, reason): said on
  /// the page beside the convergence charts.
  std::vector<std::pair<std::string, std::string>> notConverged;
};

/// What the report found.
struct ReportSummary {
  std::filesystem::path page;  ///< DIR/index.html
  int checks = 0, failedChecks = 0, unsolvedDecks = 0;
  int notApplied = 0;  ///< checks whose `when:` was false at the decks' parameter values
};

/// Builds the report; progress lines go to `log`. Throws std::invalid_argument, before any
/// work, when problemsDir holds no deck or DIR/index.html exists without a charts/ directory
/// beamrotor wrote; std::runtime_error when a file cannot be written.
ReportSummary writeReport(const ReportOptions& options, std::ostream& log);

}  // namespace beamrotor::verify

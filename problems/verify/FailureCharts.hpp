// The failure-case studies (problems/scenes/README.md, section 6) as report charts, each with the
// sentence that says what it shows.
#pragma once

#include <vector>

#include "problems/verify/StudyChart.hpp"

namespace beamrotor::verify {

/// How far the expensive studies go (the report uses the defaults; tests ask for less).
struct FailureChartOptions {
  int largestMesh = 1000000;  ///< over-refinement: elements of the finest cantilever
};

/// Computes every study and returns its charts, in report order.
std::vector<StudyChart> failureCharts(const FailureChartOptions& options = {});

}  // namespace beamrotor::verify

// `beamrotor overlay`: the static diagrams of several solved decks on one chart, one line per
// deck (the pump rod paper compares its variants A and B this way).
#pragma once

#include <filesystem>
#include <string>
#include <vector>

#include "problems/output/structure/Charts.hpp"
#include "problems/run/RunResult.hpp"

namespace beamrotor {

/// One deck's run on the overlay, keyed by `label` (also its CSV file's stem).
struct OverlaidRun {
  std::string label;
  const RunResult* run = nullptr;
};

/// The first static analysis of `run` that has diagrams along a line (a line model, not a
/// frame of members), or null.
const AnalysisOutcome* overlaidAnalysis(const RunResult& run);

/// Writes into dir (an empty directory being filled): `<label>_fields.csv` per run (the
/// fields table of its overlaidAnalysis, which every run must have) and the chart
/// `overlay.svg/png/gp` with the diagrams in `shown`, one line per run; markers at the named
/// points that lie at the same place in every run; tables and chart in `units` (inUnits).
/// Returns whether gnuplot drew it.
bool writeOverlay(const std::filesystem::path& dir, const std::vector<OverlaidRun>& runs,
                  const std::vector<Diagram>& shown, const OutputUnits& units = {});

}  // namespace beamrotor

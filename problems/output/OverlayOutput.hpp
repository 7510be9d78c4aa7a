// `beamrotor overlay`: the static diagrams of several solved decks on one chart, one line per
// deck (the pump rod paper compares its variants A and B this way).
#pragma once

#include <filesystem>
#include <string>
#include <vector>

#include "problems/output/files/CsvTable.hpp"
#include "problems/output/structure/Charts.hpp"
#include "problems/run/RunResult.hpp"
#include "problems/run/Study.hpp"

namespace beamrotor {

/// One deck's run on the overlay, keyed by `label` (also its CSV file's stem).
struct OverlaidRun {
  std::string label;
  const RunResult* run = nullptr;
};

/// The decks of an overlay solved, each without its sweep and with `sets` ("NAME=VALUE")
/// applied. Throws DeckError for a deck without a static analysis along a line or given twice,
/// before anything is written, and as solveStudy does.
std::vector<Study> solveOverlaid(const std::vector<std::string>& deckPaths,
                                 const std::vector<std::string>& sets);

/// The diagrams `quantity` names: a diagramName, or "all" for every one; empty for any other
/// text.
std::vector<Diagram> overlaidDiagrams(const std::string& quantity);

/// The first static analysis of `run` that has diagrams along a line (a line model, not a
/// frame of members), or null.
const AnalysisOutcome* overlaidAnalysis(const RunResult& run);

/// `<label>_fields.csv` of one run: the fields table of its overlaidAnalysis (which it must
/// have; std::invalid_argument otherwise) in `units` (inUnits), titled by its file name.
CsvTable overlaidTable(const OverlaidRun& r, const OutputUnits& units);

/// Writes into dir (an empty directory being filled): `<label>_fields.csv` per run (the
/// fields table of its overlaidAnalysis, which every run must have) and the chart
/// `overlay.svg/png/gp` with the diagrams in `shown`, one line per run; markers at the named
/// points that lie at the same place in every run; tables and chart in `units` (inUnits).
/// Returns whether gnuplot drew it.
bool writeOverlay(const std::filesystem::path& dir, const std::vector<OverlaidRun>& runs,
                  const std::vector<Diagram>& shown, const OutputUnits& units = {});

}  // namespace beamrotor

// The files of a moving-load analysis: its results.json entry (each quantity's influence line
// as exact cubic pieces and its envelope with the governing positions), <stem>_influence.csv
// (the lines sampled along the path, both limits where one jumps), <stem>_envelopes.csv and
// the chart <stem>_influence (one panel per quantity, the governing positions marked).
#pragma once

#include <filesystem>
#include <string>
#include <vector>

#include "problems/deck/OutputUnits.hpp"
#include "problems/output/JsonWriter.hpp"
#include "problems/output/files/CsvTable.hpp"
#include "problems/run/RunResult.hpp"

namespace beamrotor {

/// <stem>_influence.csv (columns in SI, each named, for inUnits) and <stem>_envelopes.csv
/// (rows in `units` already, each naming its unit).
std::vector<CsvTable> movingTables(const MovingLoadOutcome& m, const std::string& stem,
                                   const OutputUnits& units);

/// The analysis' entry in results.json.
Json movingJson(const AnalysisOutcome& a, const std::string& stem);

/// The chart <stem>_influence, in `units`.
void drawMovingCharts(const std::filesystem::path& dir, const MovingLoadOutcome& m,
                      const std::string& stem, const std::string& caption,
                      const OutputUnits& units);

}  // namespace beamrotor

// A train's torsion results beyond its modes: the interference diagram (the natural
// frequencies and the excitation orders against the reference shaft's speed) and its
// crossings, the torques and twists at the operating speed per order, and the response over
// the speed range; as CSV tables, results.json entries and charts.
#pragma once

#include <filesystem>
#include <string>
#include <vector>

#include "problems/deck/OutputUnits.hpp"
#include "problems/output/JsonWriter.hpp"
#include "problems/output/files/CsvTable.hpp"
#include "problems/run/TorsionOutcome.hpp"

namespace beamrotor {

/// <stem>_interference.csv (when the analysis has a speed range), <stem>_crossings.csv (when
/// it has orders), <stem>_torques.csv (at the operating speed) and <stem>_response.csv (over
/// the range, when it has harmonic torques). The torques table, whose rows mix torques and
/// twists, is in `units` already (each row names its unit); the others are SI (rpm for speeds)
/// and take `units` by inUnits.
std::vector<CsvTable> torsionTables(const TorsionOutcome& t, const std::string& stem,
                                   const OutputUnits& units = {});

/// results.json's `train` entry: shafts and their speed ratios, crossings, the response.
Json torsionTrainJson(const TorsionOutcome& t, const std::string& stem);

/// The interference diagram and the response against speed, from the tables above as written
/// in `units`.
void drawTorsionCharts(const std::filesystem::path& dir, const TorsionOutcome& t,
                       const std::string& stem, const std::string& caption,
                       const OutputUnits& units = {});

}  // namespace beamrotor

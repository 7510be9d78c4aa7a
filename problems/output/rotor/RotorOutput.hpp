// The files of the rotor analyses in a results directory: tables prepared before anything is
// written (so a NaN fails the run before the first byte), then CSV, charts and VTK.
#pragma once

#include <filesystem>
#include <optional>
#include <string>

#include "problems/output/files/CsvTable.hpp"
#include "problems/run/RunResult.hpp"

namespace beamrotor {

/// The tables of one rotor analysis (those of its type).
struct PreparedRotor {
  std::optional<CsvTable> modes;      ///< rotor: <stem>_modes.csv
  std::optional<CsvTable> campbell;   ///< campbell: <stem>_campbell.csv
  std::optional<CsvTable> critical;   ///< campbell: <stem>_critical_speeds.csv
  std::optional<CsvTable> unbalance;  ///< unbalance: <stem>_unbalance.csv
  std::optional<CsvTable> api684;     ///< unbalance with operating range: <stem>_api684.csv
  std::optional<CsvTable> frf;        ///< frequency-response: <stem>_frf.csv
  std::optional<CsvTable> bearings;   ///< campbell with plain journal bearings: <stem>_bearings.csv
  std::optional<CsvTable> map;        ///< critical-speed-map: <stem>_map.csv
  std::optional<CsvTable> mapBearings;  ///< critical-speed-map: <stem>_map_bearings.csv
  std::optional<CsvTable> mapCrossings;  ///< critical-speed-map: <stem>_map_crossings.csv
  std::optional<CsvTable> bearingLoads;  ///< bearing-loads: <stem>_bearing_loads.csv
  std::optional<CsvTable> sag;           ///< bearing-loads: <stem>_sag.csv
};

/// Builds the tables of a solved rotor analysis (a.rotor set); throws on non-finite values.
PreparedRotor prepareRotor(const AnalysisOutcome& a, const std::string& stem);

/// Writes them into dir, with the mode VTK files and orbits (rotor) and, when `charts`, the
/// Campbell diagram or the unbalance response chart under `caption`.
void writeRotorFiles(const PreparedRotor& p, const AnalysisOutcome& a, const std::string& stem,
                     const Model& model, const std::filesystem::path& dir,
                     const std::string& caption, bool charts);

}  // namespace beamrotor

// The files of the rotor analyses in a results directory: tables prepared before anything is
// written (so a NaN fails the run before the first byte), then CSV, charts and VTK.
#pragma once

#include <filesystem>
#include <optional>
#include <string>

#include "problems/deck/OutputUnits.hpp"
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
  std::optional<CsvTable> levelOne;      ///< level1-stability: <stem>_level1.csv
  std::optional<CsvTable> runUp;         ///< run-up: <stem>_runup.csv
  std::optional<CsvTable> runUpHistory;  ///< run-up: <stem>_runup_history.csv
  /// rotor: <stem>_orbits.csv (modeOrbitsTable; it needs the model, so prepareRun adds it).
  std::optional<CsvTable> orbits;
};

/// Builds the tables of a solved rotor analysis, those of its kind (a rigid body has none:
/// results.json holds all of it); throws on non-finite values.
PreparedRotor prepareRotor(const RotorModesResult& r, const std::string& stem);
PreparedRotor prepareRotor(const CampbellOutcome& r, const std::string& stem);
PreparedRotor prepareRotor(const UnbalanceOutcome& r, const std::string& stem);
PreparedRotor prepareRotor(const RigidBodyOutcome& r, const std::string& stem);
PreparedRotor prepareRotor(const FrequencyResponseOutcome& r, const std::string& stem);
PreparedRotor prepareRotor(const CriticalSpeedMapOutcome& r, const std::string& stem);
PreparedRotor prepareRotor(const BearingLoadsOutcome& r, const std::string& stem);
PreparedRotor prepareRotor(const LevelOneOutcome& r, const std::string& stem);
PreparedRotor prepareRotor(const RunUpOutcome& r, const std::string& stem);

/// Where and how one rotor analysis writes its files.
struct RotorFiles {
  const PreparedRotor& tables;  ///< prepareRotor's, of the same result
  const std::string& stem;      ///< file stem of its files
  const Model& model;           ///< for the mode shapes and orbits (VTK)
  const std::filesystem::path& dir;
  std::string caption;  ///< of its charts (shortened where too long to fit above one)
  bool charts = true;   ///< whether to draw them
  OutputUnits units = {};  ///< the units the tables are in and the charts show (OutputUnits.hpp)
};

/// Writes the tables into f.dir, with the mode VTK files and orbits (rotor) and, when
/// f.charts, the charts of its kind (orbits, Campbell and stability diagrams, unbalance
/// response, frequency response, critical-speed map).
void writeRotorFiles(const RotorFiles& f, const RotorModesResult& r);
void writeRotorFiles(const RotorFiles& f, const CampbellOutcome& r);
void writeRotorFiles(const RotorFiles& f, const UnbalanceOutcome& r);
void writeRotorFiles(const RotorFiles& f, const RigidBodyOutcome& r);
void writeRotorFiles(const RotorFiles& f, const FrequencyResponseOutcome& r);
void writeRotorFiles(const RotorFiles& f, const CriticalSpeedMapOutcome& r);
void writeRotorFiles(const RotorFiles& f, const BearingLoadsOutcome& r);
void writeRotorFiles(const RotorFiles& f, const LevelOneOutcome& r);
void writeRotorFiles(const RotorFiles& f, const RunUpOutcome& r);

}  // namespace beamrotor

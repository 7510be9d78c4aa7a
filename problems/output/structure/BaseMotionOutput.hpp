// What a base-motion analysis writes: the sweep table (per named point that moves: the
// transmissibility and the relative and absolute displacement amplitudes along the ground's
// direction; the base force), its results.json entry and the transfer-function chart.
#pragma once

#include <filesystem>
#include <string>

#include "fem/modal/BaseMotion.hpp"
#include "problems/output/JsonWriter.hpp"
#include "problems/output/files/CsvTable.hpp"

namespace beamrotor {

/// <stem>_base_motion.csv.
CsvTable baseMotionTable(const BaseMotionResult& r, const Model& model, const std::string& stem);

/// The analysis' results.json entry.
Json baseMotionJson(const std::string& type, const std::string& name, const BaseMotionResult& r,
                    const Model& model);

/// <stem>_base_motion.png/svg: transmissibility and relative displacement against frequency
/// (log scales), one curve per named point that moves; reads the table's file.
void drawBaseMotionChart(const std::filesystem::path& dir, const CsvTable& table,
                         const std::string& stem, const std::string& caption);

}  // namespace beamrotor

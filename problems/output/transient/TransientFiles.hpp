// The files of a transient analysis: the named histories as CSV and as a chart against time,
// and the stored frames as VTU files in a .pvd time series for ParaView.
#pragma once

#include <filesystem>
#include <string>

#include "fem/model/Model.hpp"
#include "problems/output/files/CsvTable.hpp"
#include "problems/run/TransientOutcome.hpp"

namespace beamrotor {

/// One row per sample time: t (s), then one column per named history (its unit).
CsvTable historyTable(const std::string& title, const TransientOutcome& transient);

/// Writes historyCsv(stem) from `history`, frameVtu(stem, i) per frame and collectionPvd(stem)
/// listing them at their times, and, when `caption` is not empty, the history chart.
void writeTransientFiles(const std::filesystem::path& dir, const Model& model,
                         const std::string& stem, const TransientOutcome& transient,
                         const CsvTable& history, const std::string& caption);

}  // namespace beamrotor

// The static diagrams of a short sweep on one chart, one line per value of the swept parameter
// (the pump rod paper's figures show three stroke positions this way).
#pragma once

#include <filesystem>
#include <string>
#include <vector>

#include "problems/deck/OutputUnits.hpp"
#include "problems/output/files/CsvTable.hpp"
#include "problems/run/RunResult.hpp"

namespace beamrotor {

/// A sweep over this many values or fewer draws its static diagrams overlaid (more lines
/// would be unreadable; the sweep charts show long sweeps).
inline constexpr std::size_t kOverlaidValues = 5;

/// Draws chartName in dir from each value's fields table (fields[i], a staticFieldsTable),
/// written as csvFiles[i] relative to dir; markers at the named points that lie at the same
/// place in every run; in `units`, those the tables are in. Nothing is drawn for more than kOverlaidValues values.
void drawOverlaidDiagrams(const std::filesystem::path& dir, const std::string& caption,
                          const std::string& chartName, const SweepResult& sweep,
                          const std::vector<const CsvTable*>& fields,
                          const std::vector<std::string>& csvFiles,
                          const OutputUnits& units = {});

}  // namespace beamrotor

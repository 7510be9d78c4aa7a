// Writes what a solved deck produced into an output directory: results.json, CSV tables,
// VTK files for ParaView and gnuplot charts. The directory appears complete or not at all
// (written into a temporary sibling, then renamed).
#pragma once

#include <filesystem>

#include "problems/run/RunResult.hpp"

namespace beamrotor {

/// All outputs of one run into dir (replacing an earlier run's directory).
void writeRunOutputs(const RunResult& run, const std::filesystem::path& dir);

/// All outputs of a sweep into dir: one sub-directory per value plus the sweep tables,
/// charts and a .pvd series.
void writeSweepOutputs(const SweepResult& sweep, const std::filesystem::path& dir);

}  // namespace beamrotor

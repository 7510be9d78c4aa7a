// Writes what a solved deck produced into an output directory: results.json, CSV tables,
// VTK files for ParaView and gnuplot charts. The directory appears complete or not at all
// (written into a temporary sibling, then renamed).
#pragma once

#include <filesystem>
#include <functional>

#include "problems/deck/OutputChoices.hpp"
#include "problems/output/PreparedRun.hpp"
#include "problems/run/RunResult.hpp"

namespace beamrotor {

/// More files a caller puts into the results directory being written (e.g. exported
/// matrices), so that they are replaced with it.
using AlsoWrite = std::function<void(const std::filesystem::path&)>;

/// All outputs of one run into dir (replacing an earlier run's directory), the charts in the
/// format `choices` names, drawn together at the end (ChartBatch).
void writeRunOutputs(const RunResult& run, const std::filesystem::path& dir,
                     const OutputChoices& choices = {}, const AlsoWrite& also = {});
/// The same from the run already prepared (prepareRun, PreparedRun.hpp), whose extremes the
/// caller may go on to read (the summary).
void writePreparedRun(const PreparedRun& prepared, const std::filesystem::path& dir,
                      const OutputChoices& choices = {}, const AlsoWrite& also = {});

/// All outputs of a sweep into dir: the sweep tables and charts, and with choices.pointFiles
/// one sub-directory per value (its results without charts) and a .pvd series over them.
void writeSweepOutputs(const SweepResult& sweep, const std::filesystem::path& dir,
                       const OutputChoices& choices = {}, const AlsoWrite& also = {});

}  // namespace beamrotor

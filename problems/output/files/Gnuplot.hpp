// Draws charts by running gnuplot on a generated script kept in the results directory (so a
// reader can restyle and re-run it). Charts are a convenience: when gnuplot is missing or
// fails, the run still succeeds and one warning goes to stderr; a chart that could not be
// written (a full device) fails the run like any other file. Many charts are drawn by a few
// gnuplot processes side by side, each drawing its share one script after another.
//
// gnuplot runs shell commands (`system`, `!`, backquotes, file names starting with '<' or
// '|'), so text from a deck reaches a script only through gnuplotText and gnuplotFile, which
// make it an inert single-quoted literal, and gnuplot is started without a shell.
#pragma once

#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include "problems/deck/OutputChoices.hpp"

namespace beamrotor {

/// A chart as gnuplot commands; drawChart writes it as `<name>.gp` and draws `<name>.png`
/// and/or `<name>.svg` from it.
struct ChartScript {
  std::string name;     ///< file stem, e.g. "static_diagrams"
  std::string purpose;  ///< one line for the script's header comment
  int width = 900;      ///< pixels
  int height = 600;
  /// Commands that draw the chart (after terminal and output are set); data files are named
  /// relative to the directory, where gnuplot runs.
  std::string body;
  /// Data the body reads, defined once before it (gnuplot datablocks, `$name << EOD` .. `EOD`,
  /// values separated by ','); empty when the body reads files.
  std::string data{};
};

/// The gnuplot to run: $BEAMROTOR_GNUPLOT when set (a path, or a name looked up on PATH),
/// else "gnuplot" on PATH; nullopt when there is none.
std::optional<std::filesystem::path> findGnuplot();

/// Inside a ChartBatch (ChartBatch.hpp) on this thread: hands the chart to it, to be drawn
/// with the others in the batch's format; returns whether the batch took it (false when it
/// draws no charts). Otherwise draws it now, as drawCharts does, as SVG and PNG; returns
/// whether both images were drawn.
bool drawChart(const std::filesystem::path& dir, const ChartScript& chart);

/// Writes dir/<name>.gp for each chart, then draws them with at most `processes` gnuplot
/// processes side by side in dir, each given its share of the charts (balanced by an estimate
/// of each chart's cost: a fixed part and the data files it reads), drawing `format` (<name>.png by pngcairo when gnuplot has it,
/// else png; <name>.svg). Returns how many charts were drawn. Without gnuplot it warns once
/// per process; a chart gnuplot fails on costs that chart only: a warning with gnuplot's
/// message (kept in <name>.log), and the charts after it are drawn by a new process. Throws
/// std::runtime_error when a script cannot be written or gnuplot left an image cut short (a
/// full device), std::invalid_argument for a chart name outside the directory (before
/// anything is written).
int drawCharts(const std::filesystem::path& dir, const std::vector<ChartScript>& charts,
               ChartFormat format, int processes);

/// text as a gnuplot string expression of single-quoted literals, inert whatever it holds:
/// control characters and invalid UTF-8 become '?' (a line break would end the script line),
/// a quote is joined in as "'", and the characters enhanced-text terminals read as markup
/// ('_' for a subscript, ...) are escaped.
std::string gnuplotText(const std::string& text);

/// `file` when it is a relative path inside the results directory made of parts of letters,
/// digits, '-', '_' and '.' (not "." or "..") joined by '/'; throws std::invalid_argument
/// otherwise. So no name gnuplot reads as a command ('<' or '|' first) or a special file.
std::string confinedFileName(const std::string& file);

/// A file in the chart's directory as a gnuplot single-quoted literal, "./" first; see
/// confinedFileName.
std::string gnuplotFile(const std::string& file);

}  // namespace beamrotor

// Draws charts by running gnuplot on a generated script kept in the results directory (so a
// reader can restyle and re-run it). Charts are a convenience: when gnuplot is missing or
// fails, the run still succeeds and one warning goes to stderr.
#pragma once

#include <filesystem>
#include <optional>
#include <string>

namespace beamrotor {

/// A chart as gnuplot commands; drawChart writes it as `<name>.gp` and draws `<name>.svg` and
/// `<name>.png` from it.
struct ChartScript {
  std::string name;     ///< file stem, e.g. "static_diagrams"
  std::string purpose;  ///< one line for the script's header comment
  int width = 900;      ///< pixels
  int height = 600;
  /// Commands that draw the chart (after terminal and output are set); data files are named
  /// relative to the directory, where gnuplot runs.
  std::string body;
};

/// The gnuplot to run: $BEAMROTOR_GNUPLOT when set (a path, or a name looked up on PATH),
/// else "gnuplot" on PATH; nullopt when there is none.
std::optional<std::filesystem::path> findGnuplot();

/// Writes dir/<name>.gp and runs gnuplot in dir, drawing <name>.svg and <name>.png (pngcairo
/// when gnuplot has it, else png). Returns whether both images were drawn. Without gnuplot it
/// warns once per process; when gnuplot fails it warns with gnuplot's message
/// (kept in <name>.log). Never throws because of gnuplot.
bool drawChart(const std::filesystem::path& dir, const ChartScript& chart);

/// text as a gnuplot single-quoted string literal, safe for enhanced-text terminals (the
/// characters gnuplot would read as markup, e.g. '_' for a subscript, are escaped).
std::string gnuplotText(const std::string& text);

/// A file name as a gnuplot single-quoted string literal (no markup escaping).
std::string gnuplotFile(const std::string& file);

}  // namespace beamrotor

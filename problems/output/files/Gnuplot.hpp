// Draws charts by running gnuplot on a generated script kept in the results directory (so a
// reader can restyle and re-run it). Charts are a convenience: when gnuplot is missing or
// fails, the run still succeeds and one warning goes to stderr; a chart that could not be
// written (a full device) fails the run like any other file.
//
// gnuplot runs shell commands (`system`, `!`, backquotes, file names starting with '<' or
// '|'), so text from a deck reaches a script only through gnuplotText and gnuplotFile, which
// make it an inert single-quoted literal, and gnuplot is started without a shell.
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
  /// Data the body reads, defined once before it (gnuplot datablocks, `$name << EOD` .. `EOD`,
  /// values separated by ','); empty when the body reads files.
  std::string data{};
};

/// The gnuplot to run: $BEAMROTOR_GNUPLOT when set (a path, or a name looked up on PATH),
/// else "gnuplot" on PATH; nullopt when there is none.
std::optional<std::filesystem::path> findGnuplot();

/// Writes dir/<name>.gp and runs gnuplot in dir, drawing <name>.svg and <name>.png (pngcairo
/// when gnuplot has it, else png). Returns whether both images were drawn. Without gnuplot it
/// warns once per process; when gnuplot fails it warns with gnuplot's message (kept in
/// <name>.log). Throws std::runtime_error when the script cannot be written or gnuplot
/// succeeded but left an image cut short (a full device).
bool drawChart(const std::filesystem::path& dir, const ChartScript& chart);

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

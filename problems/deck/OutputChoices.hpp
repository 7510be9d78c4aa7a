// What a results directory holds besides results.json and the tables: charts in which format,
// What a results directory holds besides results.json and the tables: charts in which format,
// a sweep's results per value, which load cases get their own files, and the units shown. A
// deck's `output:` block chooses, the command line (`--charts`, `--point-files`,
// `--full-tables`, `--all-cases`, `--units`) overrides it.
#pragma once

#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "problems/deck/OutputUnits.hpp"

namespace beamrotor {

/// The image files each chart becomes: PNG (the default), SVG, both, or no chart at all.
enum class ChartFormat { png, svg, both, none };

/// "png", "svg", "both", "none".
std::string_view chartFormatName(ChartFormat format);
/// The format a name names; nullopt for any other text.
std::optional<ChartFormat> chartFormatNamed(std::string_view name);
/// Every name, in the order above.
const std::vector<std::string>& chartFormatNames();

struct OutputChoices {
  ChartFormat charts = ChartFormat::png;
  /// A sweep: every value's own results directory (value_000/, ...) besides the sweep's tables.
  bool pointFiles = false;
  /// A long line's fields table at every station (5 an element), not thinned to what a chart
  /// and a reader need (ThinnedStations.hpp).
  bool fullTables = false;
  /// The units of the summary, tables and charts; none set: each writer's own.
  OutputUnits units = {};
  /// Statics with combinations: every load case's and combination's own VTK file, not only
  /// those of the combinations that govern (writtenCases, CaseEnvelope.hpp).
  bool allCases = false;
};

/// The choices a deck's `output:` block makes; each unset one leaves the default.
struct DeckOutput {
  std::optional<ChartFormat> charts;
  std::optional<bool> pointFiles;
  std::optional<bool> fullTables;
  OutputUnits units = {};  ///< the command line's set over the deck's, quantity by quantity
  std::optional<bool> allCases;
};

/// The deck's choices over the defaults, then the command line's over them.
OutputChoices chooseOutput(const DeckOutput& deck, const DeckOutput& commandLine);

}  // namespace beamrotor

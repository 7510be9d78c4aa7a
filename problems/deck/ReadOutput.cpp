// Deck reader: `output:`, what the results directory holds besides results.json and the tables
// (OutputChoices.hpp).
#include "problems/deck/ReaderContext.hpp"

namespace beamrotor::reader {

void readOutput(Context& c) {
  auto block = c.root.get("output");
  if (!block || block->isNull()) return;
  block->allowOnly({"charts", "point_files", "full_tables", "all_cases"}, "output");
  if (auto charts = block->get("charts"))
    c.deck.output.charts = chartFormatNamed(charts->choice(chartFormatNames()));
  if (auto pointFiles = block->get("point_files")) c.deck.output.pointFiles = pointFiles->boolean();
  if (auto fullTables = block->get("full_tables")) c.deck.output.fullTables = fullTables->boolean();
  if (auto allCases = block->get("all_cases")) c.deck.output.allCases = allCases->boolean();
}

}  // namespace beamrotor::reader

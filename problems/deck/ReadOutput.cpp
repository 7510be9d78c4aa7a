// Deck reader: `output:`, what the results directory holds besides results.json and the tables
// (OutputChoices.hpp), and the units of the summary, tables and charts (OutputUnits.hpp).
#include "problems/deck/ReaderContext.hpp"

namespace beamrotor::reader {

void readOutput(Context& c) {
  auto block = c.root.get("output");
  if (!block || block->isNull()) return;
  block->allowOnly({"charts", "point_files", "full_tables", "units", "all_cases"}, "output");
  if (auto charts = block->get("charts"))
    c.deck.output.charts = chartFormatNamed(charts->choice(chartFormatNames()));
  if (auto pointFiles = block->get("point_files")) c.deck.output.pointFiles = pointFiles->boolean();
  if (auto fullTables = block->get("full_tables")) c.deck.output.fullTables = fullTables->boolean();
  if (auto units = block->get("units"); units && !units->isNull()) {
    units->allowOnly(outputQuantityNames(), "output units");
    for (const auto& [quantity, unit] : units->entries()) try {
        c.deck.output.units.set(quantity, unit.label(40));
      } catch (const std::invalid_argument& e) {
        unit.fail(e.what());
      }
  }
  if (auto allCases = block->get("all_cases")) c.deck.output.allCases = allCases->boolean();
}

}  // namespace beamrotor::reader

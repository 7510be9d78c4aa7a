// Tables in the user's output units (see TableUnits.hpp).
#include "problems/output/files/TableUnits.hpp"

namespace beamrotor {

CsvTable inUnits(CsvTable table, const OutputUnits& units) {
  if (!units.any()) return table;
  // Counts and text keep their cells; a count with a unit (none so far) would be a number.
  for (std::size_t c = 0; c < table.columns().size(); ++c) {
    const OutputUnits::Shown shown = units.of(table.columns()[c].unit);
    table.convertColumn(c, shown.factor, shown.unit);
  }
  return table;
}

}  // namespace beamrotor

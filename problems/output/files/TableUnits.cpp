// Tables in the user's output units (see TableUnits.hpp).
#include "problems/output/files/TableUnits.hpp"

#include <variant>

namespace beamrotor {

CsvTable inUnits(const CsvTable& table, const OutputUnits& units) {
  if (!units.any()) return table;
  std::vector<CsvColumn> columns = table.columns();
  std::vector<double> factors;
  for (CsvColumn& c : columns) {
    const OutputUnits::Shown shown = units.of(c.unit);
    factors.push_back(shown.factor);
    c.unit = shown.unit;
  }
  CsvTable converted(table.title(), std::move(columns));
  converted.reserveRows(table.rowCount());
  std::vector<CsvCell> row(factors.size());
  for (std::size_t r = 0; r < table.rowCount(); ++r) {
    for (std::size_t c = 0; c < factors.size(); ++c) {
      row[c] = table.cell(r, c);
      // Counts and text keep their cells; a count with a unit (none so far) would be a number.
      if (double* x = std::get_if<double>(&row[c]); x && factors[c] != 1) *x *= factors[c];
    }
    converted.addRow(row);
  }
  return converted;
}

}  // namespace beamrotor

// A table shown in the output units a user chose (OutputUnits.hpp): every column whose unit
// names a quantity they set is multiplied into their unit and its `# units:` entry renamed.
// Column names stay as they are (they are what a chart, a script or `--quantity` looks up).
#pragma once

#include "problems/deck/OutputUnits.hpp"
#include "problems/output/files/CsvTable.hpp"

namespace beamrotor {

/// `table` in `units`, converted in place; the table itself when none is set.
CsvTable inUnits(CsvTable table, const OutputUnits& units);

}  // namespace beamrotor

// study.csv, a design study's table: one row per point, in point order,
//   point, <each varied parameter>, <each output>, then per check "<name>" (the computed
//   value) and "<name> pass" (1 or 0), and status ("ok" or the point's error).
// The names line is followed, as in every CSV table (CsvTable.hpp), by a comment line of each
// column's unit ("# units: ,m,Pa,,"): the unit the deck gives the column's numbers (SI, rpm
// for a critical speed or a bare *_rpm parameter), whatever output units are chosen, so that a
// study resumed with other units continues the same file.
// Numbers carry 17 significant digits, so the file gives back every double bit for bit; a cell
// is empty where the point has no value (a failed point, a check that does not apply there).
#pragma once

#include <optional>
#include <ostream>
#include <string>

#include "problems/study/StudyPoint.hpp"

namespace beamrotor {

/// The header: the names line and, when some column has a unit, the units line (each with
/// its newline).
std::string studyCsvHeader(const StudyPlan& plan);

/// One row (with its newline).
std::string studyCsvRow(const StudyRow& row);

/// A row read back from its line (without the newline), `shape` giving the number of
/// parameters, outputs and checks: the numbers bit for bit, an empty cell as NaN (a check's
/// pass cell as -1). nullopt when the line is not such a row; the cost is not in the table.
std::optional<StudyRow> parseStudyCsvRow(const std::string& line, const StudyRow& shape);

}  // namespace beamrotor

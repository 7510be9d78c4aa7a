// Numerical thresholds shared by the analyses (kept apart from the solver headers so option
// structs can name them without pulling in UMFPACK).
#pragma once

namespace beamrotor {

/// rcond below this means the matrix is singular to working precision: its pivots span more
/// than the ~15 decimal digits a double carries, so a solve returns round-off, not an answer.
inline constexpr double kSingularRcond = 1e-14;

}  // namespace beamrotor

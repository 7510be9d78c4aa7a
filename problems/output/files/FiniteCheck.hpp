// Refuses results holding NaN or infinity before anything is written: a results directory
// with "null" in its JSON or "nan" in its tables would pass for a finished run.
#pragma once

#include "problems/run/RunResult.hpp"

namespace beamrotor {

/// Throws std::runtime_error naming the first non-finite number of the run (parameter,
/// check, node coordinate, displacement, reaction, mode ...), e.g.
/// "analysis 'tip' (static): displacement at node 4 'end' (x = 2, 0, 0) uy is nan".
void requireFinite(const RunResult& run);

}  // namespace beamrotor

// The results.json entry of a transient analysis:
//   {type, name, scheme, dt, steps, end_time, factorizations,
//    maxima {<history>_max: largest |value|}, histories {name: {unit, max, min, max_abs,
//    time_of_max_abs, final}}, [stability {omega_max, dt_critical, dt_critical_safe, method}],
//    energy_balance_error, impacts [{time, stop, velocity_before, velocity_after}], warnings,
//    time_s, files {history_csv, [pvd, vtu [...]]}}
#pragma once

#include "problems/output/JsonWriter.hpp"
#include "problems/run/RunResult.hpp"

namespace beamrotor {

/// The entry of analysis `a` (which holds a transient outcome).
Json transientJson(const AnalysisOutcome& a);

}  // namespace beamrotor

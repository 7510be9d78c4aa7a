// The title every chart of a run carries: which deck and analysis, and only the parameters a
// reader needs to tell this chart from another of the same deck, rounded.
#pragma once

#include <string>

#include "problems/deck/OutputUnits.hpp"
#include "problems/run/RunResult.hpp"

namespace beamrotor {

/// "pump_rod: static" and, on a second line, the parameters set on the command line and the
/// deck's `report:` values, each to 4 significant digits with its SI unit when the deck gave
/// one ("eta = 0.2 m, F = 1.25e+04 N"). `what` follows the analysis' name; the parameter `left`
/// (a sweep's, which `what` names) is not listed. Lines of parameters are kept to a chart's
/// width.
/// Values in the user's `units` where they set the parameter's quantity.
std::string chartCaption(const RunResult& run, const std::string& analysis,
                         const std::string& what = "", const std::string& left = "",
                         const OutputUnits& units = {});

}  // namespace beamrotor

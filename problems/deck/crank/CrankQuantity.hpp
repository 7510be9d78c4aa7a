// The check quantities of a crank-slider analysis (problems/scenes/README.md section 3):
//   crank PROPERTY              a figure of the mechanism at the analysis' crank speed
//   crank PROPERTY at LAMBDA    a row of the harmonic table (A2, A4, A6, v_ratio, K_lambda) at
//                               one of the analysis' `lambdas:`
//   crank PROPERTY at PHI deg   the first crank's motion or a load at crank angle PHI (deg),
//                               exact kinematics at the analysis' crank speed
// problems/run/RunCrankSlider.hpp measures them.
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "problems/deck/FieldUnits.hpp"
#include "problems/deck/Quantity.hpp"

namespace beamrotor {

/// The properties `crank PROPERTY` may name, those a table row has (`... at LAMBDA`) and those
/// at a crank angle (`... at PHI deg`).
const std::vector<std::string>& crankPropertyNames();
const std::vector<std::string>& crankTablePropertyNames();
const std::vector<std::string>& crankAnglePropertyNames();

/// Fills q when `words` starts with "crank" and returns true; false otherwise; throws
/// std::invalid_argument when it is a crank quantity written wrongly.
bool parseCrankQuantity(const std::vector<std::string>& words, Quantity& q);

/// The unit of a crank quantity's reference (m/s for v_max, N for F1, ...).
FieldUnit crankReferenceUnit(const Quantity& q);

}  // namespace beamrotor

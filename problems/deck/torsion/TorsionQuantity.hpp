// The check quantities of a torsion analysis of a train at its operating speed (the peak over
// a revolution of the steady response to its harmonic torques):
//   torsion torque NAME      the vibratory torque (N m) in coupling or gear NAME, or the
//                            largest along shaft NAME
//   torsion twist STATION    the vibratory twist (rad) of station SHAFT.NAME
// problems/run/RunTorsion.hpp measures them.
#pragma once

#include <string>
#include <vector>

#include "problems/deck/Quantity.hpp"

namespace beamrotor {

/// Fills q when `words` starts with "torsion" and returns true; false otherwise; throws
/// std::invalid_argument when it is a torsion quantity written wrongly.
bool parseTorsionQuantity(const std::vector<std::string>& words, Quantity& q);

}  // namespace beamrotor

// Running a crank-slider analysis (problems/scenes/README.md section 3) from the kinematics
// and load formulas of problems/scenes/CrankSlider.hpp, and measuring its check quantities
// (problems/deck/crank/CrankQuantity.hpp).
#pragma once

#include "problems/deck/crank/DeckCrank.hpp"
#include "problems/deck/Quantity.hpp"
#include "problems/run/CrankSliderOutcome.hpp"

namespace beamrotor {

/// The motion over a revolution, the figures, loads and table of the mechanism `d`.
CrankSliderOutcome runCrankSlider(const DeckCrankSlider& d);

/// The value of a `crank ...` quantity; throws std::invalid_argument when the outcome lacks
/// what it needs (the reader prevents that for decks).
double measureCrank(const Quantity& q, const CrankSliderOutcome& c);

}  // namespace beamrotor

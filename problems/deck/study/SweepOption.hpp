// A sweep given on the command line instead of in the deck:
//   --sweep eta=0:0.4:8        from 0 to 0.4 in 8 steps (9 values)
//   --sweep eta=0,0.1,0.25     the listed values
// Values are numbers or expressions of constants, with or without a unit (`L=4m:8m:4`); one
// with a unit must have the parameter's dimension in the deck.
#pragma once

#include <string>

#include "problems/deck/Deck.hpp"

namespace beamrotor {

/// Parses the option for `deck` (whose parameters it must name). Throws DeckError naming the
/// deck and the option.
DeckSweep parseSweepOption(const std::string& argument, const Deck& deck);

/// The SI value of `text`, typed on the command line for `parameter` of `deck`: a number or
/// an expression of constants, with or without a unit (one with a unit must have the
/// parameter's dimension). Throws DeckError naming the deck and `place`.
double parameterValueOption(const std::string& text, const std::string& parameter,
                            const Deck& deck, const DeckPlace& place);

}  // namespace beamrotor

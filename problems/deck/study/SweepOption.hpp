// A sweep given on the command line instead of in the deck:
//   --sweep eta=0:0.4:8        from 0 to 0.4 in 8 steps (9 values)
//   --sweep eta=0,0.1,0.25     the listed values
// Values are numbers or expressions of constants, with or without a unit (`L=4m:8m:4`); one
// with a unit must have the parameter's dimension in the deck. The values a deck itself gives
// for a parameter away from the parameter (a sweep's `values:`, a study's ranges and
// distributions) follow the same rule.
#pragma once

#include <string>

#include "problems/deck/Deck.hpp"
#include "problems/deck/parse/Field.hpp"

namespace beamrotor {

class ExpressionEvaluator;

/// Parses the option for `deck` (whose parameters it must name). Throws DeckError naming the
/// deck and the option.
DeckSweep parseSweepOption(const std::string& argument, const Deck& deck);

/// The SI value of `text`, typed on the command line for `parameter` of `deck`: a number or
/// an expression of constants, with or without a unit (one with a unit must have the
/// parameter's dimension). Throws DeckError naming the deck and `place`.
double parameterValueOption(const std::string& text, const std::string& parameter,
                            const Deck& deck, const DeckPlace& place);

/// The dimension `parameter` of `deck` has: its unit's when the deck writes it with one, else
/// the one the fields it flows into tell (Deck::bareDimensions); dimensionless when neither.
Dimension parameterDimension(const Deck& deck, const std::string& parameter);

/// The SI value of field `f`, a value for `parameter` whose dimension is `own`: a bare number
/// is in SI units of `own`, one with a unit must have `own`. Fails at `f` naming the field
/// ("values[1] expects a length (m), got a time (s)"), and for a parameter that neither a unit
/// nor a field gives a dimension, says so.
double parameterValue(const Field& f, const ExpressionEvaluator& evaluator,
                      const std::string& parameter, const Dimension& own);

}  // namespace beamrotor

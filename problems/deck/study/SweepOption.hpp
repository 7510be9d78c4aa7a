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

/// The unit `parameter` of `deck` has: its dimension's SI unit when the deck writes it with a
/// unit, else the dimension the fields it flows into tell (Deck::bareDimensions) with the bare
/// unit of such a field (rpm for a *_rpm field); dimensionless when neither.
FieldUnit parameterUnit(const Deck& deck, const std::string& parameter);
/// The dimension of parameterUnit.
Dimension parameterDimension(const Deck& deck, const std::string& parameter);

/// Why a value with a unit (of dimension `given`) cannot be given to `parameter`, whose bare
/// numbers a field reads in a unit other than SI (own.bareSize, e.g. rpm): converting it to
/// SI would be read as rpm. nullopt when it can.
std::optional<std::string> unitInBareUnit(const std::string& parameter, const Dimension& given,
                                          const FieldUnit& own);

/// The value of field `f`, a value for `parameter` whose unit is `own`: a bare number as it
/// is (in own's bare unit), one with a unit must have own's dimension and is then in SI.
/// Fails at `f` naming the field ("values[1] expects a length (m), got a time (s)"), for a
/// parameter that neither a unit nor a field gives a dimension says so, and refuses a unit
/// for a parameter read in a bare unit other than SI (unitInBareUnit).
double parameterValue(const Field& f, const ExpressionEvaluator& evaluator,
                      const std::string& parameter, const FieldUnit& own);

}  // namespace beamrotor

// The dimension a parameter written without a unit takes from the fields it flows into
// (FORMAT.md, Units): `length: L` makes L a length, `at: L/2` too, `b: 0.715 - eta` makes eta
// a length (the bare numbers take the field's dimension, so the whole sum does), `A: d^2`
// makes d a length. Only a field (or derived value) whose expression holds that one bare name
// and no other tells; derived values pass it on to the name they hold. An expression in a
// dimensionless field tells nothing (`when: eta == 0.4`), and the most direct uses decide
// (the field is the name, then an expression of it, then through named values), since a bare
// number in an expression may carry a unit (`mass: Q / 9.80665` with Q a weight). A
// command-line value with a unit for such a parameter must have that dimension and is then
// used in SI, exactly as the bare SI number would be.
#pragma once

#include <map>
#include <string>
#include <vector>

#include "problems/deck/parse/DeckError.hpp"
#include "problems/deck/parse/NumericReads.hpp"

namespace beamrotor {

class ExpressionEvaluator;

/// Where a bare parameter's dimension was found: the first field that told it.
struct BareUse {
  Dimension dimension;
  std::string file;
  DeckPlace place;  ///< field: the field's path
  /// The field's bare unit in SI units (2 pi / 60 for a *_rpm field): the parameter's bare
  /// numbers are in it, so a value with a unit cannot stand for one (BareParameters.cpp).
  double bareSize = 1;
};

/// "deck.yaml:12 (segments[0].length)", for messages.
std::string describeUse(const BareUse& use);

/// The dimensions of the bare `parameters` that `reads` tell. `texts`: the expression of each
/// bare named value (parameter or derived) as written, for the names they pass a dimension
/// on to; `evaluator` knows every name. Throws DeckError at the later use when a parameter
/// flows into two dimensions, naming both.
std::map<std::string, BareUse> bareDimensions(
    const std::vector<NumericRead>& reads, const ExpressionEvaluator& evaluator,
    const std::vector<std::string>& parameters,
    const std::vector<std::pair<std::string, std::string>>& texts);

}  // namespace beamrotor

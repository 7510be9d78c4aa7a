#include "problems/deck/study/Overrides.hpp"

#include "problems/deck/parse/DeckError.hpp"
#include "problems/deck/parse/Expression.hpp"

namespace beamrotor {

ParameterOverride parseOverride(const std::string& argument, const std::string& deckPath) {
  const DeckPlace place{0, 0, "--set " + argument};
  const std::size_t eq = argument.find('=');
  if (eq == std::string::npos)
    throw DeckError(deckPath, place, "expected NAME=VALUE, e.g. --set eta=0.2");
  ParameterOverride o;
  o.name = argument.substr(0, eq);
  o.text = argument;
  while (!o.name.empty() && o.name.back() == ' ') o.name.pop_back();
  if (!ExpressionEvaluator::isIdentifier(o.name))
    throw DeckError(deckPath, place, "'" + o.name + "' is not a parameter name");
  try {
    const ExpressionEvaluator constants;
    const Amount a = constants.amount(argument.substr(eq + 1));
    o.value = a.si;
    if (!a.anyDimension && !a.dimension.dimensionless()) o.dimension = a.dimension;
  } catch (const ExpressionError& e) {
    // The deck's parameters are not known yet when the command line is read.
    // The reason names the value ("cannot evaluate 'abc': unknown name 'abc'").
    throw DeckError(deckPath, place,
                    std::string(e.what()) +
                        " (a --set value is a number or an expression of numbers, pi and "
                        "functions, e.g. 0.4/2 or 2*pi, not of other parameters)");
  }
  return o;
}

std::optional<std::string> overrideMismatch(const std::string& name, const Dimension& given,
                                            const Dimension& expected) {
  if (given == expected) return std::nullopt;
  std::string why =
      name + " expects " + describeDimension(expected) + ", got " + describeDimension(given);
  if (expected.dimensionless())
    why += " (the deck gives " + name +
           " without a unit, and no field whose value holds it alone tells its dimension: give "
           "a plain number in SI units, or write the deck's value with its unit)";
  return why;
}

const ParameterOverride* findOverride(const std::vector<ParameterOverride>& overrides,
                                      const std::string& name) {
  const ParameterOverride* found = nullptr;
  for (const ParameterOverride& o : overrides)
    if (o.name == name) found = &o;
  return found;
}

}  // namespace beamrotor

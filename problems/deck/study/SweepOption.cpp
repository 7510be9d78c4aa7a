#include "problems/deck/study/SweepOption.hpp"

#include <algorithm>
#include <cmath>
#include <sstream>

#include "problems/deck/DeckReader.hpp"
#include "problems/deck/parse/Expression.hpp"
#include "problems/deck/study/Overrides.hpp"
#include "problems/deck/parse/Suggest.hpp"

namespace beamrotor {

namespace {

std::vector<std::string> split(const std::string& text, char separator) {
  std::vector<std::string> parts;
  std::istringstream in(text);
  for (std::string part; std::getline(in, part, separator);) parts.push_back(part);
  if (!text.empty() && text.back() == separator) parts.emplace_back();
  return parts;
}

}  // namespace

FieldUnit parameterUnit(const Deck& deck, const std::string& parameter) {
  for (const auto& [name, d] : deck.dimensions)
    if (name == parameter) return FieldUnit{d};
  for (const auto& [name, unit] : deck.bareDimensions)
    if (name == parameter) return unit;
  return FieldUnit{};
}

Dimension parameterDimension(const Deck& deck, const std::string& parameter) {
  return parameterUnit(deck, parameter).dimension;
}

std::optional<std::string> unitInBareUnit(const std::string& parameter, const Dimension& given,
                                          const FieldUnit& own) {
  if (own.bareSize == 1 || given.dimensionless()) return std::nullopt;
  const std::string unit = own.bareSize == kRpmField.bareSize ? std::string("rpm")
                                                              : "units of " + siUnitOf(own.dimension);
  return parameter + " has no unit in the deck and flows into a field that reads bare numbers " +
         "in " + unit + ": give its value without a unit, in " + unit +
         ", or write the deck's value of " + parameter + " with its unit";
}

double parameterValue(const Field& f, const ExpressionEvaluator& evaluator,
                      const std::string& parameter, const FieldUnit& own) {
  const Amount a = f.amount(evaluator);
  const bool hasUnit = !a.anyDimension && !a.dimension.dimensionless();
  if (own.dimension.dimensionless() && hasUnit) {
    // Nothing tells what a unit here should be (a bare parameter no field gives a dimension):
    // say so, as for the same value typed on the command line.
    if (auto why = overrideMismatch(parameter, a.dimension, own.dimension)) f.fail(*why);
  }
  if (hasUnit)
    if (auto why = unitInBareUnit(parameter, a.dimension, own)) f.fail(*why);
  // A bare number is taken as it is, in the parameter's own bare unit.
  return f.number(evaluator, FieldUnit{own.dimension});
}

double parameterValueOption(const std::string& text, const std::string& parameter,
                            const Deck& deck, const DeckPlace& place) {
  const FieldUnit own = parameterUnit(deck, parameter);  // values with a unit must have it
  Amount a;
  try {
    a = ExpressionEvaluator().amount(text);
  } catch (const ExpressionError& e) {
    throw DeckError(deck.path, place, e.what());
  }
  if (!a.anyDimension && !a.dimension.dimensionless()) {
    if (auto why = overrideMismatch(parameter, a.dimension, own.dimension))
      throw DeckError(deck.path, place, *why);
    if (auto why = unitInBareUnit(parameter, a.dimension, own))
      throw DeckError(deck.path, place, *why);
  }
  return a.si;
}

DeckSweep parseSweepOption(const std::string& argument, const Deck& deck) {
  const DeckPlace place{0, 0, "--sweep " + argument};
  auto fail = [&](const std::string& why) -> DeckError { return DeckError(deck.path, place, why); };
  const std::size_t eq = argument.find('=');
  if (eq == std::string::npos)
    throw fail("expected NAME=FROM:TO:STEPS or NAME=V1,V2,..., e.g. --sweep eta=0:0.4:8");
  DeckSweep sweep;
  sweep.parameter = argument.substr(0, eq);
  sweep.place = place;
  std::vector<std::string> names;
  for (const auto& [name, v] : deck.parameters) names.push_back(name);
  if (std::find(names.begin(), names.end(), sweep.parameter) == names.end())
    throw fail("no parameter '" + sweep.parameter + "' in this deck" +
               didYouMean(sweep.parameter, names) + " (parameters: " + joinNames(names) + ")");

  const std::string spec = argument.substr(eq + 1);
  auto value = [&](const std::string& text) {
    return parameterValueOption(text, sweep.parameter, deck, place);
  };
  const std::vector<std::string> range = split(spec, ':');
  if (range.size() == 3) {
    const double from = value(range[0]), to = value(range[1]), steps = value(range[2]);
    if (steps != std::round(steps) || steps < 1 || steps > kMaxSweepValues - 1)
      throw fail("STEPS must be a whole number from 1 to " + std::to_string(kMaxSweepValues - 1));
    const int n = int(steps);
    for (int i = 0; i < n; ++i) sweep.values.push_back(from + (to - from) * i / n);
    sweep.values.push_back(to);
    if (!std::isfinite(to - from))
      throw fail("FROM and TO are too far apart for the values between them to be numbers");
  } else if (range.size() == 1) {
    for (const std::string& v : split(spec, ',')) sweep.values.push_back(value(v));
    if (int(sweep.values.size()) > kMaxSweepValues)
      throw fail("at most " + std::to_string(kMaxSweepValues) + " values");
  } else {
    throw fail("expected FROM:TO:STEPS or V1,V2,... after '='");
  }
  return sweep;
}

}  // namespace beamrotor

// Check quantities of the crank-slider analysis, as read from a deck (see CrankQuantity.hpp).
#include "problems/deck/crank/CrankQuantity.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <stdexcept>

#include "problems/deck/parse/Suggest.hpp"

namespace beamrotor {

namespace {

struct CrankProperty {
  const char* name;
  Dimension dimension;
};

/// Every property with the dimension of its value; the order is the one FORMAT.md lists.
const std::vector<CrankProperty>& crankProperties() {
  static const std::vector<CrankProperty> all{
      {"lambda", dim::none},
      {"v_max", dim::velocity},
      {"v_mean", dim::velocity},
      {"v_ratio", dim::none},
      {"a_max", dim::acceleration},
      {"beta_max", dim::angle},
      {"beta_dot_max", dim::angularSpeed},
      {"beta_ddot_max", Dimension::of(0, 0, -2, 1)},
      {"beta_ddot_max_first_order", Dimension::of(0, 0, -2, 1)},
      {"A2", dim::none},
      {"A4", dim::none},
      {"A6", dim::none},
      {"rotating_mass", dim::mass},
      {"reciprocating_mass", dim::mass},
      {"F1", dim::force},
      {"F2", dim::force},
      {"F_rotating", dim::force},
      {"F1_total", dim::force},
      {"F2_total", dim::force},
      {"cranks_F1", dim::force},
      {"cranks_F2", dim::force},
      {"cranks_rotating", dim::force},
      {"moment_max", dim::moment},
      {"moment_max_first_order", dim::moment},
      {"delivery", Dimension::of(3, 0, -1, 0)},
      {"K_lambda", dim::none}};
  return all;
}

/// The first crank's motion and loads at one crank angle (exact kinematics, uniform speed).
const std::vector<CrankProperty>& crankAngleProperties() {
  static const std::vector<CrankProperty> all{
      {"x", dim::length},
      {"v", dim::velocity},
      {"a", dim::acceleration},
      {"beta", dim::angle},
      {"beta_dot", dim::angularSpeed},
      {"beta_ddot", Dimension::of(0, 0, -2, 1)},
      {"moment", dim::moment},
      {"force", dim::force},
      {"cranks_force", dim::force}};
  return all;
}

const CrankProperty* findCrankProperty(const std::vector<CrankProperty>& among,
                                       const std::string& name) {
  for (const CrankProperty& p : among)
    if (name == p.name) return &p;
  return nullptr;
}

/// Reads the number in `crank PROPERTY at NUMBER ...`; throws unless it is all number.
double crankAtNumber(const std::string& word, const char* what) {
  std::size_t used = 0;
  double value = 0;
  try {
    value = std::stod(word, &used);
  } catch (const std::exception&) {
    used = 0;
  }
  if (used != word.size() || !std::isfinite(value))
    throw std::invalid_argument(std::string(what) + " '" + word + "' is not a number");
  return value;
}

/// The names of `properties`, leaving out `except`.
std::vector<std::string> crankNamesOf(const std::vector<CrankProperty>& properties,
                                      const std::string& except) {
  std::vector<std::string> out;
  for (const CrankProperty& p : properties)
    if (p.name != except) out.push_back(p.name);
  return out;
}

}  // namespace

const std::vector<std::string>& crankPropertyNames() {
  // K_lambda is a table column only.
  static const std::vector<std::string> names = crankNamesOf(crankProperties(), "K_lambda");
  return names;
}

const std::vector<std::string>& crankAnglePropertyNames() {
  static const std::vector<std::string> names = crankNamesOf(crankAngleProperties(), "");
  return names;
}

const std::vector<std::string>& crankTablePropertyNames() {
  static const std::vector<std::string> names{"A2", "A4", "A6", "v_ratio", "K_lambda"};
  return names;
}

bool parseCrankQuantity(const std::vector<std::string>& words, Quantity& q) {
  if (words[0] != "crank") return false;
  const bool atLambda = words.size() == 4 && words[2] == "at";
  const bool atAngle = words.size() == 5 && words[2] == "at" && words[4] == "deg";
  if (words.size() != 2 && !atLambda && !atAngle)
    throw std::invalid_argument(
        "expected 'crank PROPERTY', 'crank PROPERTY at LAMBDA' or 'crank PROPERTY at PHI deg'");
  const std::string& p = words[1];
  const std::vector<std::string>& names = atAngle    ? crankAnglePropertyNames()
                                          : atLambda ? crankTablePropertyNames()
                                                     : crankPropertyNames();
  if (std::find(names.begin(), names.end(), p) == names.end())
    throw std::invalid_argument("'" + p + "' is not a crank-slider " +
                                (atAngle    ? "quantity at a crank angle"
                                 : atLambda ? "table column"
                                            : "property") +
                                didYouMean(p, names) + " (" + joinNames(names) + ")");
  q.kind = Quantity::Kind::crankSlider;
  q.property = p;
  if (atLambda) {
    q.lambda = crankAtNumber(words[3], "lambda");
    if (!(q.lambda > 0 && q.lambda < 1))
      throw std::invalid_argument("lambda '" + words[3] + "' must be a number between 0 and 1");
  }
  if (atAngle) q.crankAngle = crankAtNumber(words[3], "crank angle") * std::numbers::pi / 180;
  return true;
}

FieldUnit crankReferenceUnit(const Quantity& q) {
  const CrankProperty* p =
      findCrankProperty(q.crankAngle ? crankAngleProperties() : crankProperties(), q.property);
  return {p ? p->dimension : dim::none};
}

}  // namespace beamrotor

// Check quantities of the crank-slider analysis, as read from a deck (see CrankQuantity.hpp).
#include "problems/deck/CrankQuantity.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "problems/deck/Suggest.hpp"

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

const CrankProperty* findCrankProperty(const std::string& name) {
  for (const CrankProperty& p : crankProperties())
    if (name == p.name) return &p;
  return nullptr;
}

}  // namespace

const std::vector<std::string>& crankPropertyNames() {
  static const std::vector<std::string> names = [] {
    std::vector<std::string> out;
    for (const CrankProperty& p : crankProperties())
      if (std::string(p.name) != "K_lambda") out.push_back(p.name);
    return out;
  }();
  return names;
}

const std::vector<std::string>& crankTablePropertyNames() {
  static const std::vector<std::string> names{"A2", "A4", "A6", "v_ratio", "K_lambda"};
  return names;
}

bool parseCrankQuantity(const std::vector<std::string>& words, Quantity& q) {
  if (words[0] != "crank") return false;
  if (words.size() != 2 && !(words.size() == 4 && words[2] == "at"))
    throw std::invalid_argument("expected 'crank PROPERTY' or 'crank PROPERTY at LAMBDA'");
  const std::string& p = words[1];
  const std::vector<std::string>& names =
      words.size() == 2 ? crankPropertyNames() : crankTablePropertyNames();
  if (std::find(names.begin(), names.end(), p) == names.end())
    throw std::invalid_argument("'" + p + "' is not a crank-slider " +
                                (words.size() == 2 ? "property" : "table column") +
                                didYouMean(p, names) + " (" + joinNames(names) + ")");
  q.kind = Quantity::Kind::crankSlider;
  q.property = p;
  if (words.size() == 4) {
    std::size_t used = 0;
    try {
      q.lambda = std::stod(words[3], &used);
    } catch (const std::exception&) {
      used = 0;
    }
    if (used != words[3].size() || !(q.lambda > 0 && q.lambda < 1))
      throw std::invalid_argument("lambda '" + words[3] + "' must be a number between 0 and 1");
  }
  return true;
}

FieldUnit crankReferenceUnit(const Quantity& q) {
  const CrankProperty* p = findCrankProperty(q.property);
  return {p ? p->dimension : dim::none};
}

}  // namespace beamrotor

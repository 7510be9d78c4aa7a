// The units of the summary, tables and charts (see OutputUnits.hpp).
#include "problems/deck/OutputUnits.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <stdexcept>

#include "problems/deck/FieldUnits.hpp"
#include "problems/deck/ShownFieldUnit.hpp"
#include "problems/deck/parse/Suggest.hpp"
#include "problems/deck/parse/UnitText.hpp"

namespace beamrotor {

namespace {

/// A base quantity raised to a power, as a part of a compound one.
struct Part {
  const char* quantity;
  int power;
};

struct QuantityKind {
  const char* name;
  Dimension dimension;
  std::vector<Part> parts;  ///< empty for a base quantity
};

/// Every quantity, base ones first. Dimensions differ, so a column's unit names one at most.
const std::vector<QuantityKind>& quantityKinds() {
  static const std::vector<QuantityKind> kinds{
      {"length", dim::length, {}},
      {"force", dim::force, {}},
      {"stress", dim::pressure, {}},
      {"mass", dim::mass, {}},
      {"angle", dim::angle, {}},
      {"time", dim::time, {}},
      {"speed", dim::angularSpeed, {}},
      {"frequency", dim::frequency, {}},
      {"moment", dim::moment, {{"force", 1}, {"length", 1}}},
      {"stiffness", dim::stiffness, {{"force", 1}, {"length", -1}}},
      {"damping", dim::damping, {{"force", 1}, {"time", 1}, {"length", -1}}},
      {"rotational_stiffness",
       dim::rotationalStiffness,
       {{"force", 1}, {"length", 1}, {"angle", -1}}},
      {"compliance", Dimension::of(0, -1, 2, 0), {{"length", 1}, {"force", -1}}},
      {"velocity", dim::velocity, {{"length", 1}, {"time", -1}}},
      {"acceleration", dim::acceleration, {{"length", 1}, {"time", -2}}},
  };
  return kinds;
}

const QuantityKind* kindNamed(const std::string& name) {
  for (const QuantityKind& k : quantityKinds())
    if (name == k.name) return &k;
  return nullptr;
}

/// The SI unit of a base quantity, as a part of a compound one's name.
const char* siName(const std::string& quantity) {
  return quantity == "length" ? "m" : quantity == "force" ? "N" : quantity == "time" ? "s" : "rad";
}

/// "m, km, cm, mm": the table's units of dimension d.
std::string unitsOf(const Dimension& d) {
  std::string list;
  for (const Unit& u : units())
    if (u.dimension == d) {
      if (!list.empty()) list += ", ";
      list += u.name;
    }
  return list;
}

/// What `quantity` takes, for a message: "m, km, cm, mm, um, in, ft" or "a moment (N m),
/// e.g. 'kN m'".
std::string takes(const QuantityKind& k) {
  if (k.dimension == dim::angularSpeed) return unitsOf(dim::angularSpeed) + ", rad/s, Hz";
  if (k.dimension == dim::frequency) return unitsOf(dim::frequency) + ", rpm, rad/s";
  if (k.parts.empty()) return unitsOf(k.dimension);
  return describeDimension(k.dimension) + " written as a product of units, e.g. '" +
         siUnitOf(k.dimension) + "'";
}

}  // namespace

const std::vector<std::string>& outputQuantityNames() {
  static const std::vector<std::string> names = [] {
    std::vector<std::string> list;
    for (const QuantityKind& k : quantityKinds()) list.emplace_back(k.name);
    return list;
  }();
  return names;
}

void OutputUnits::set(const std::string& quantity, const std::string& unit) {
  const QuantityKind* kind = kindNamed(quantity);
  if (!kind)
    throw std::invalid_argument("no quantity '" + quantity + "'" +
                                didYouMean(quantity, outputQuantityNames()) + " (units are set for " +
                                joinNames(outputQuantityNames()) + ")");
  const std::optional<UnitSize> size = unitSize(unit);
  if (!size || unit.find_first_not_of(' ') == std::string::npos)
    throw std::invalid_argument("'" + unit + "' is no unit; " + quantity + " takes " +
                                takes(*kind));
  // A turn is 2 pi radians: a speed in Hz turns per second, a frequency in rpm cycles a minute.
  constexpr double turn = 2 * std::numbers::pi;
  double si = size->si;
  if (kind->dimension == dim::angularSpeed && size->dimension == dim::frequency)
    si *= turn;
  else if (kind->dimension == dim::frequency && size->dimension == dim::angularSpeed)
    si /= turn;
  else if (size->dimension != kind->dimension)
    throw std::invalid_argument("'" + unit + "' is " + describeDimension(size->dimension) +
                                ", not " + describeDimension(kind->dimension) + "; " + quantity +
                                " takes " + takes(*kind));
  std::erase_if(settings_, [&](const auto& s) { return s.first == quantity; });
  std::erase_if(chosen_, [&](const Chosen& c) { return c.quantity == quantity; });
  settings_.emplace_back(quantity, unit);
  chosen_.push_back({quantity, unit, si});
}

OutputUnits OutputUnits::overlaid(const OutputUnits& over) const {
  OutputUnits both = *this;
  for (const auto& [quantity, unit] : over.settings_) both.set(quantity, unit);
  return both;
}

const OutputUnits::Chosen* OutputUnits::find(const std::string& quantity) const {
  for (const Chosen& c : chosen_)
    if (c.quantity == quantity) return &c;
  return nullptr;
}

std::optional<OutputUnits::Chosen> OutputUnits::chosen(const Dimension& d) const {
  const auto kind = std::find_if(quantityKinds().begin(), quantityKinds().end(),
                                 [&](const QuantityKind& k) { return k.dimension == d; });
  if (kind == quantityKinds().end()) return std::nullopt;
  if (const Chosen* set = find(kind->name)) return *set;
  if (kind->parts.empty()) return std::nullopt;
  // Composed of its parts, when any of them is set: "kN m", "kN s/mm", "mm/s^2".
  bool anySet = false;
  std::string above, below;
  double si = 1;
  for (const Part& part : kind->parts) {
    const Chosen* set = find(part.quantity);
    anySet = anySet || set;
    std::string name = set ? set->unit : siName(part.quantity);
    if (std::abs(part.power) > 1) name += "^" + std::to_string(std::abs(part.power));
    std::string& side = part.power > 0 ? above : below;
    if (!side.empty()) side += " ";
    side += name;
    si *= std::pow(set ? set->si : 1.0, part.power);
  }
  if (!anySet) return std::nullopt;
  return Chosen{kind->name, below.empty() ? above : above + "/" + below, si};
}

OutputUnits::Shown OutputUnits::of(const std::string& unit) const {
  const std::optional<UnitSize> size = unit.empty() ? std::nullopt : unitSize(unit);
  const std::optional<Chosen> target = size ? chosen(size->dimension) : std::nullopt;
  if (!target) return {1, unit};
  return {size->si / target->si, target->unit};
}

OutputUnits::Shown OutputUnits::ofSI(const Dimension& d) const {
  if (const std::optional<Chosen> target = chosen(d)) return {1 / target->si, target->unit};
  return {1, siUnitOf(d)};
}

bool OutputUnits::sets(const std::string& unit) const {
  const std::optional<UnitSize> size = unit.empty() ? std::nullopt : unitSize(unit);
  return size && chosen(size->dimension);
}

OutputUnits::Shown OutputUnits::valueIn(const std::string& unit, const Shown& own) const {
  return sets(unit) ? of(unit) : own;
}

OutputUnits::Shown OutputUnits::columnIn(const std::string& unit, const Shown& own) const {
  return sets(unit) ? Shown{1, of(unit).unit} : own;
}

OutputUnits parseOutputUnits(const std::string& list) {
  const auto trimmed = [](std::string s) {
    s.erase(0, s.find_first_not_of(' '));
    s.erase(s.find_last_not_of(' ') + 1);
    return s;
  };
  OutputUnits units;
  std::size_t start = 0;
  while (start <= list.size()) {
    const std::size_t comma = std::min(list.find(',', start), list.size());
    const std::string item = list.substr(start, comma - start);
    const std::size_t equals = item.find('=');
    if (equals == std::string::npos)
      throw std::invalid_argument("'" + trimmed(item) +
                                  "' is no QUANTITY=UNIT (e.g. length=mm,force=kN)");
    units.set(trimmed(item.substr(0, equals)), trimmed(item.substr(equals + 1)));
    start = comma + 1;
  }
  return units;
}

// ShownFieldUnit.hpp: bare field units shown in the output units (kept in this file: one
// translation unit for the output units).
std::string bareUnitName(const FieldUnit& field) {
  if (field.bareSize != 1)
    for (const Unit& u : units())
      if (u.dimension == field.dimension && u.si == field.bareSize) return u.name;
  return siUnitOf(field.dimension);
}

OutputUnits::Shown shownField(const OutputUnits& units, const FieldUnit& field) {
  if (const std::string si = siUnitOf(field.dimension); !si.empty() && units.sets(si)) {
    const OutputUnits::Shown shown = units.ofSI(field.dimension);
    return {field.bareSize * shown.factor, shown.unit};
  }
  return {1, bareUnitName(field)};
}

FieldUnit checkQuantityUnit(const std::string& quantity) {
  // evaluate() appends the load case a check reads to the deck's phrase.
  const std::string phrase = quantity.substr(0, quantity.find(" (case "));
  try {
    return referenceUnit(parseQuantity(phrase));
  } catch (const std::invalid_argument&) {
    return {};
  }
}

}  // namespace beamrotor

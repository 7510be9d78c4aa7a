#include "problems/deck/parse/Units.hpp"

#include <cmath>
#include <cstdio>
#include <numbers>

namespace beamrotor {

namespace {

struct NamedDimension {
  Dimension dimension;
  const char* noun;  // with its article
  const char* unit;  // SI
};

const std::vector<NamedDimension>& namedDimensions() {
  static const std::vector<NamedDimension> named{
      {dim::none, "a dimensionless number", ""},
      {dim::length, "a length", "m"},
      {dim::area, "an area", "m^2"},
      {Dimension::of(3, 0, 0, 0), "a volume", "m^3"},
      {dim::secondMoment, "a second moment of area", "m^4"},
      {dim::mass, "a mass", "kg"},
      {dim::time, "a time", "s"},
      {dim::angle, "an angle", "rad"},
      {dim::force, "a force", "N"},
      {dim::forcePerLength, "a force per length or a stiffness", "N/m"},
      {dim::moment, "a moment", "N m"},
      {dim::pressure, "a pressure or stress", "Pa"},
      {dim::density, "a density", "kg/m^3"},
      {dim::power, "a power", "W"},
      {dim::inertia, "a mass moment of inertia", "kg m^2"},
      {dim::massLength, "a mass times a length (an unbalance)", "kg m"},
      {dim::rotationalStiffness, "a rotational stiffness", "N m/rad"},
      {dim::damping, "a damping coefficient", "N s/m"},
      {dim::rotationalDamping, "a rotational damping coefficient", "N m s/rad"},
      {dim::frequency, "a frequency", "Hz"},
      {dim::angularSpeed, "an angular speed", "rad/s"},
      {dim::velocity, "a velocity", "m/s"},
      {dim::acceleration, "an acceleration", "m/s^2"},
      {dim::lengthPerAngle, "a length per angle", "m/rad"},
      {Dimension::of(1, 1, -2, -1), "a moment per angle", "N/rad"},
      {Dimension::of(1, 0, -1, -1), "a velocity per angle", "m/(rad s)"},
      {dim::temperature, "a temperature difference", "K"},
      {dim::thermalExpansion, "a thermal expansion coefficient", "1/K"},
  };
  return named;
}

std::string exponentText(double e) {
  if (e == 1) return "";
  char buf[32];
  std::snprintf(buf, sizeof buf, "^%g", e);
  return buf;
}

}  // namespace

std::string siUnitOf(const Dimension& d) {
  for (const NamedDimension& n : namedDimensions())
    if (n.dimension == d) return n.unit;
  static const char* const base[] = {"m", "kg", "s", "rad", "K"};
  std::string out;
  for (int i = 0; i < Dimension::kBases; ++i) {
    if (d.exponents[i] == 0) continue;
    if (!out.empty()) out += " ";
    out += base[i] + exponentText(d.exponents[i]);
  }
  return out;
}

std::string describeDimension(const Dimension& d) {
  for (const NamedDimension& n : namedDimensions())
    if (n.dimension == d)
      return d.dimensionless() ? n.noun : std::string(n.noun) + " (" + n.unit + ")";
  return "a quantity in " + siUnitOf(d);
}

const std::vector<Unit>& units() {
  constexpr double pi = std::numbers::pi;
  static const std::vector<Unit> all{
      {"m", 1, dim::length},       {"km", 1e3, dim::length},
      {"cm", 1e-2, dim::length},   {"mm", 1e-3, dim::length},
      {"um", 1e-6, dim::length},   {"in", 0.0254, dim::length},
      {"ft", 0.3048, dim::length}, {"kg", 1, dim::mass},
      {"g", 1e-3, dim::mass},      {"t", 1e3, dim::mass},
      {"s", 1, dim::time},         {"ms", 1e-3, dim::time},
      {"N", 1, dim::force},        {"kN", 1e3, dim::force},
      {"MN", 1e6, dim::force},     {"Pa", 1, dim::pressure},
      {"kPa", 1e3, dim::pressure}, {"MPa", 1e6, dim::pressure},
      {"GPa", 1e9, dim::pressure}, {"bar", 1e5, dim::pressure},
      {"rad", 1, dim::angle},      {"deg", pi / 180, dim::angle},
      {"rev", 2 * pi, dim::angle}, {"rpm", 2 * pi / 60, dim::angularSpeed},
      {"Hz", 1, dim::frequency},   {"kHz", 1e3, dim::frequency},
      {"K", 1, dim::temperature},
      {"W", 1, dim::power},        {"kW", 1e3, dim::power},
      {"MW", 1e6, dim::power},
  };
  return all;
}

std::optional<Unit> findUnit(const std::string& name) {
  for (const Unit& u : units())
    if (name == u.name) return u;
  return std::nullopt;
}

}  // namespace beamrotor

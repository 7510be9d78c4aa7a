// Physical dimensions and the units a deck may write after a number (issue 16): `210 GPa`,
// `6000 mm`, `12 kN/m`, `3000 rpm`, `20 K`. A dimension is a vector of exponents of five base
// dimensions: length (m), mass (kg), time (s), plane angle (rad) and temperature (K, a
// temperature change: decks give differences, never absolute temperatures). Angle is kept apart from
// the dimensionless numbers so that an angular speed (rad/s, rpm) is never taken for a
// frequency (Hz = 1/s) and a rotational stiffness (N m/rad) never for a moment.
#pragma once

#include <array>
#include <numbers>
#include <optional>
#include <string>
#include <vector>

namespace beamrotor {

struct Dimension {
  /// Exponents of length, mass, time, angle and temperature; whole numbers for every named
  /// dimension, but an intermediate result such as sqrt(A) may have halves.
  std::array<double, 5> exponents{0, 0, 0, 0, 0};

  static constexpr int kLength = 0, kMass = 1, kTime = 2, kAngle = 3, kTemperature = 4;
  static constexpr int kBases = 5;
  static constexpr Dimension of(double length, double mass, double time, double angle,
                                double temperature = 0) {
    return Dimension{{length, mass, time, angle, temperature}};
  }
  bool dimensionless() const { return *this == Dimension{}; }
  bool operator==(const Dimension&) const = default;
};

/// The dimensions a deck's fields have, by name.
namespace dim {
inline constexpr Dimension none = Dimension::of(0, 0, 0, 0);
inline constexpr Dimension length = Dimension::of(1, 0, 0, 0);
inline constexpr Dimension area = Dimension::of(2, 0, 0, 0);
inline constexpr Dimension secondMoment = Dimension::of(4, 0, 0, 0);
inline constexpr Dimension mass = Dimension::of(0, 1, 0, 0);
inline constexpr Dimension time = Dimension::of(0, 0, 1, 0);
inline constexpr Dimension angle = Dimension::of(0, 0, 0, 1);
inline constexpr Dimension force = Dimension::of(1, 1, -2, 0);
inline constexpr Dimension forcePerLength = Dimension::of(0, 1, -2, 0);
inline constexpr Dimension moment = Dimension::of(2, 1, -2, 0);
inline constexpr Dimension pressure = Dimension::of(-1, 1, -2, 0);
inline constexpr Dimension density = Dimension::of(-3, 1, 0, 0);
inline constexpr Dimension inertia = Dimension::of(2, 1, 0, 0);
inline constexpr Dimension massLength = Dimension::of(1, 1, 0, 0);
inline constexpr Dimension stiffness = Dimension::of(0, 1, -2, 0);
inline constexpr Dimension rotationalStiffness = Dimension::of(2, 1, -2, -1);
inline constexpr Dimension damping = Dimension::of(0, 1, -1, 0);
inline constexpr Dimension rotationalDamping = Dimension::of(2, 1, -1, -1);
inline constexpr Dimension frequency = Dimension::of(0, 0, -1, 0);
inline constexpr Dimension angularSpeed = Dimension::of(0, 0, -1, 1);
inline constexpr Dimension velocity = Dimension::of(1, 0, -1, 0);
inline constexpr Dimension acceleration = Dimension::of(1, 0, -2, 0);
inline constexpr Dimension lengthPerAngle = Dimension::of(1, 0, 0, -1);
inline constexpr Dimension power = Dimension::of(2, 1, -3, 0);  // W
inline constexpr Dimension viscosity = Dimension::of(-1, 1, -1, 0);  // dynamic, Pa s
inline constexpr Dimension temperature = Dimension::of(0, 0, 0, 0, 1);  // a change, K
inline constexpr Dimension thermalExpansion = Dimension::of(0, 0, 0, 0, -1);  // 1/K
}  // namespace dim

/// What a numeric field holds, stated where the field is read: its dimension and the unit a
/// bare number in it means (SI, but rpm for the *_rpm fields). A field's value is returned in
/// that unit.
struct FieldUnit {
  // Implicit, so that a read states its dimension alone: `f.positive(ev, dim::length)`.
  constexpr FieldUnit(const Dimension& d = dim::none, double bare = 1)
      : dimension(d), bareSize(bare) {}
  Dimension dimension;
  double bareSize = 1;  ///< the bare unit in SI units (2 pi / 60 for rpm)
};

/// A *_rpm field: an angular speed whose bare number is in revolutions per minute.
inline constexpr FieldUnit kRpmField{dim::angularSpeed, 2 * std::numbers::pi / 60};

/// "a pressure (Pa)", "a length (m)", "a dimensionless number", or for an unnamed one its SI
/// unit: "a quantity in m^3 kg".
std::string describeDimension(const Dimension& d);
/// The SI unit of d, e.g. "N/m", "kg m^2", "m^3 kg"; "" when dimensionless.
std::string siUnitOf(const Dimension& d);

/// A unit a deck may write: its name, its size in SI units and its dimension.
struct Unit {
  const char* name;
  double si;
  Dimension dimension;
};

/// Every unit, in the order FORMAT.md lists them.
const std::vector<Unit>& units();
/// The unit called `name`, or nullopt.
std::optional<Unit> findUnit(const std::string& name);

}  // namespace beamrotor

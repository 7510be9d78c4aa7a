// The units a run's summary, CSV tables and charts show their numbers in (issue 43): a deck's
// `output: units:` and `--units length=mm,force=kN`. Unset, every writer keeps its own units
// (SI in the tables, with units always named); results.json is SI whatever is set.
//
// A quantity takes units of its own dimension: length (positions and displacements alike),
// force, stress, mass, angle, time, speed (an angular speed: rpm, rad/s, or Hz read as turns
// per second) and frequency (Hz, or rpm and rad/s read as cycles). The compound ones follow
// their parts unless set themselves: moment = force length, stiffness = force/length (also a
// load per length), damping = force s/length, rotational_stiffness = moment/angle,
// compliance = length/force, velocity = length/time, acceleration = length/time^2.
#pragma once

#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "problems/deck/parse/Units.hpp"

namespace beamrotor {

class OutputUnits {
 public:
  /// A number shown in these units: multiply the value by `factor`, name it `unit`.
  struct Shown {
    double factor = 1;
    std::string unit;
  };

  /// Shows `quantity` (a name of outputQuantityNames()) in `unit` ("mm", "kN m", "rpm").
  /// Throws std::invalid_argument saying what is wrong: an unknown quantity (with the list),
  /// a word that is no unit, or a unit of another dimension (naming the ones that fit).
  void set(const std::string& quantity, const std::string& unit);
  /// Whether anything is set; if not, each writer shows its own choice of units.
  bool any() const { return !settings_.empty(); }
  /// These settings with those of `over` on top (the command line's over the deck's).
  OutputUnits overlaid(const OutputUnits& over) const;
  /// The (quantity, unit) pairs as set, in order.
  const std::vector<std::pair<std::string, std::string>>& settings() const { return settings_; }

  /// A number written in `unit` (a table column's "m", "N m", "rpm"; Units.hpp's names) shown
  /// in these units; factor 1 and `unit` itself where no quantity of its dimension is set, or
  /// the text is no unit.
  Shown of(const std::string& unit) const;
  /// A number in SI units of dimension d shown in these units; unset: SI (siUnitOf).
  Shown ofSI(const Dimension& d) const;
  /// Whether the user set (or composed) the quantity a number in `unit` is.
  bool sets(const std::string& unit) const;
  /// A number a writer holds in `unit` and would show as `own` (newton metres as
  /// {1e-3, "kN m"}): in the user's unit where they set its quantity, else `own`.
  Shown valueIn(const std::string& unit, const Shown& own) const;
  /// The same for a table's column that was in `unit` before inUnits converted it: factor 1
  /// where the user set its quantity (the table holds their unit), else `own`.
  Shown columnIn(const std::string& unit, const Shown& own) const;

 private:
  struct Chosen {
    std::string quantity;
    std::string unit;
    double si;  ///< the unit's size in SI units of the quantity's dimension
  };
  /// The unit of the quantity of dimension d: set, or composed of set parts; nullopt if none.
  std::optional<Chosen> chosen(const Dimension& d) const;
  const Chosen* find(const std::string& quantity) const;

  std::vector<std::pair<std::string, std::string>> settings_;
  std::vector<Chosen> chosen_;
};

/// The quantity names `output: units:` takes, in FORMAT.md's order.
const std::vector<std::string>& outputQuantityNames();

/// "length=mm,force=kN" (spaces allowed around the names). Throws std::invalid_argument as
/// OutputUnits::set does, or for an item without '='.
OutputUnits parseOutputUnits(const std::string& list);

}  // namespace beamrotor

// What a deck's transient analysis produced: the core's TransientResult plus the deck's named
// histories (recorded dofs and values derived from them), each sampled at result.times.
#pragma once

#include <string>
#include <vector>

#include "fem/transient/TransientResults.hpp"

namespace beamrotor {

/// A history's largest and smallest value and largest |value|, each 0 for no samples.
struct HistoryExtremes {
  double max = 0, min = 0, maxAbs = 0;
};

/// One named history over the sample times.
struct NamedHistory {
  std::string name;
  std::string unit;  ///< m, rad, or as the deck says for a derived value
  std::vector<double> values;

  double max() const;     ///< largest value
  double min() const;     ///< smallest value
  double maxAbs() const;  ///< largest |value|: `<name>_max` in results.json
  HistoryExtremes extremes() const;  ///< the three above, for a reader of all three
};

struct TransientOutcome {
  TransientResult result;
  std::vector<NamedHistory> histories;  ///< in deck order

  /// The history called `name`; throws std::invalid_argument when there is none.
  const NamedHistory& history(const std::string& name) const;
  /// h at time t (s), linear between samples (exact at a sample). Throws std::invalid_argument
  /// for a time outside the run.
  double at(const NamedHistory& h, double t) const;
};

}  // namespace beamrotor

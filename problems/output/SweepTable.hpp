// What a sweep tracks across its values: each reaction component and the largest normal and
// shear stress of every static analysis, the frequencies of every modal analysis, the maxima
// (largest |value| of each named history) of every transient analysis, the critical speeds,
// smallest log decrement and onset of instability of every campbell analysis, the peak orbit
// of each response point of every unbalance analysis, the largest transmissibility and
// relative displacement of each point and the largest base force of every base-motion
// analysis, the deck's reported values and each check. Read from the runs' results.json documents, so sweep.csv,
// the sweep charts and the per-value directories report the same numbers.
#pragma once

#include <functional>
#include <string>
#include <vector>

#include "problems/output/files/CsvTable.hpp"
#include "problems/output/JsonWriter.hpp"
#include "problems/run/RunResult.hpp"

namespace beamrotor {

/// frequency, criticalSpeed and peakAmplitude quantities share a chart panel per group.
enum class SweepGroup {
  reaction,
  stress,
  frequency,
  reported,
  check,
  checkPass,
  extreme,
  criticalSpeed,
  peakAmplitude
};

/// One quantity followed over the sweep.
struct SweepQuantity {
  SweepGroup group = SweepGroup::reaction;
  std::string analysis;  ///< the analysis it belongs to; empty for checks
  std::string
      label;  ///< for a chart: "left fy", "largest stress", "mode 2", "phi_max", a check's name
  CsvColumn column;  ///< its column in sweep.csv, e.g. {"static.left.fy", "N"}
  /// Its value in one run's results.json; throws std::runtime_error when the run lacks it
  /// (a sweep whose values change the supports or analyses).
  std::function<double(const Json& runDoc)> read;
  /// Runs may lack it (a check whose `when:` condition holds for some values only): its
  /// cell is then left empty instead of failing the sweep.
  bool optional = false;
};

/// The analyses' quantities of the first run, in document order, then its reported values
/// (`report:`), then every check any run declares (in order of first appearance).
std::vector<SweepQuantity> sweepQuantities(const std::vector<Json>& runDocs);

/// sweep.csv: the parameter's column, then one column per quantity; one row per value.
CsvTable sweepTable(const std::string& title, const SweepResult& sweep,
                    const std::vector<Json>& runDocs, const std::vector<SweepQuantity>& quantities);

}  // namespace beamrotor

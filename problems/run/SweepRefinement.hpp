// An adaptive sweep: after the deck's own values, more values where the swept result changes
// fast and on both sides of every peak, until each peak is bracketed to the deck's tolerance
// (`sweep: refine:`, see FORMAT.md). A coarse sweep over a resonant response misses its peaks;
// this finds them without a dense sweep everywhere.
#pragma once

#include <functional>
#include <utility>
#include <vector>

#include "problems/deck/study/ReadSweepRefinement.hpp"
#include "problems/run/RunResult.hpp"

namespace beamrotor {

/// A result sampled at ascending parameter values.
struct SweepSamples {
  std::vector<double> values;   ///< ascending
  std::vector<double> results;  ///< one per value
};

/// The interior local maxima of the samples (a value whose result is at least its
/// neighbours' and above one of them), as (value, result), ascending in value.
std::vector<std::pair<double, double>> sweepPeaks(const SweepSamples& s);

/// The values to add next, ascending: the midpoint of each interval beside an interior local
/// maximum, and of each interval over which the result changes by more than a quarter of its
/// range so far; only intervals wider than tolerance x the larger |value| are split. Empty
/// when every peak is bracketed to the tolerance and no interval changes fast.
std::vector<double> refinementValues(const SweepSamples& s, double tolerance);

/// The refinement's quantity in every run of the sweep.
SweepSamples sweepSamples(const SweepResult& sweep, const DeckSweepRefinement& refine);

/// Runs of the sweep's deck at the given values, one per value in their order.
using SweepValueRuns = std::function<std::vector<RunResult>(const std::vector<double>&)>;

/// Refines a finished sweep in place: measures the refinement's quantity in every run, adds
/// the refinementValues (run together by runValues) in ascending place, and repeats until none
/// are left or the sweep holds refine.runs values. The sweep's values must be ascending.
/// Returns the final samples.
SweepSamples refineSweep(SweepResult& sweep, const DeckSweepRefinement& refine,
                         const SweepValueRuns& runValues);

}  // namespace beamrotor

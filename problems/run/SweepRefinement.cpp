#include "problems/run/SweepRefinement.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "problems/run/Measure.hpp"

namespace beamrotor {

namespace {

/// The refinement's quantity in one run.
double measured(const RunResult& run, const DeckSweepRefinement& refine) {
  for (const AnalysisOutcome& a : run.analyses)
    if (a.name == refine.analysis) return measure(refine.quantity, a, run);
  throw std::invalid_argument("no analysis '" + refine.analysis + "' in the run");
}

/// An interior local maximum: at least its neighbours, and above one of them.
bool isPeak(const std::vector<double>& r, std::size_t i) {
  return r[i] >= r[i - 1] && r[i] >= r[i + 1] && (r[i] > r[i - 1] || r[i] > r[i + 1]);
}

}  // namespace

SweepSamples sweepSamples(const SweepResult& sweep, const DeckSweepRefinement& refine) {
  SweepSamples s{sweep.values, {}};
  for (const RunResult& run : sweep.runs) s.results.push_back(measured(run, refine));
  return s;
}

std::vector<std::pair<double, double>> sweepPeaks(const SweepSamples& s) {
  std::vector<std::pair<double, double>> peaks;
  for (std::size_t i = 1; i + 1 < s.results.size(); ++i)
    if (isPeak(s.results, i)) peaks.emplace_back(s.values[i], s.results[i]);
  return peaks;
}

std::vector<double> refinementValues(const SweepSamples& s, double tolerance) {
  const auto& v = s.values;
  const auto& r = s.results;
  if (v.size() < 2) return {};
  const auto [lo, hi] = std::minmax_element(r.begin(), r.end());
  const double range = *hi - *lo;
  std::vector<bool> split(v.size() - 1, false);
  for (std::size_t i = 0; i + 1 < v.size(); ++i)
    split[i] = range > 0 && std::abs(r[i + 1] - r[i]) > 0.25 * range;
  for (std::size_t i = 1; i + 1 < r.size(); ++i)
    if (isPeak(r, i)) split[i - 1] = split[i] = true;
  std::vector<double> added;
  for (std::size_t i = 0; i + 1 < v.size(); ++i)
    if (split[i] && v[i + 1] - v[i] > tolerance * std::max(std::abs(v[i]), std::abs(v[i + 1])))
      added.push_back(0.5 * (v[i] + v[i + 1]));
  return added;
}

SweepSamples refineSweep(SweepResult& sweep, const DeckSweepRefinement& refine,
                         const SweepValueRuns& runValues) {
  SweepSamples s = sweepSamples(sweep, refine);
  for (;;) {
    std::vector<double> added = refinementValues(s, refine.tolerance);
    const std::size_t room = std::size_t(std::max(0, refine.runs - int(s.values.size())));
    if (added.empty() || room == 0) break;
    if (added.size() > room) added.resize(room);  // the lower values first
    std::vector<RunResult> runs = runValues(added);
    for (std::size_t k = 0; k < added.size(); ++k) {
      const double value = added[k];
      RunResult& run = runs[k];
      const double result = measured(run, refine);
      const auto at = std::upper_bound(s.values.begin(), s.values.end(), value) - s.values.begin();
      s.values.insert(s.values.begin() + at, value);
      s.results.insert(s.results.begin() + at, result);
      sweep.values.insert(sweep.values.begin() + at, value);
      sweep.runs.insert(sweep.runs.begin() + at, std::move(run));
    }
  }
  return s;
}

}  // namespace beamrotor

#include "problems/run/TransientOutcome.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace beamrotor {

double NamedHistory::max() const {
  return values.empty() ? 0.0 : *std::max_element(values.begin(), values.end());
}

double NamedHistory::min() const {
  return values.empty() ? 0.0 : *std::min_element(values.begin(), values.end());
}

double NamedHistory::maxAbs() const {
  return extremes().maxAbs;
}

HistoryExtremes NamedHistory::extremes() const {
  const double high = max(), low = min();
  return {high, low, std::max(std::abs(high), std::abs(low))};
}

const NamedHistory& TransientOutcome::history(const std::string& name) const {
  for (const NamedHistory& h : histories)
    if (h.name == name) return h;
  throw std::invalid_argument("no history '" + name + "'");
}

double TransientOutcome::at(const NamedHistory& h, double t) const {
  const std::vector<double>& times = result.times;
  if (times.empty() || h.values.size() != times.size())
    throw std::invalid_argument("history '" + h.name + "' has no samples");
  // Round-off in a time written as an expression (3*T) must not miss the last sample.
  const double slack = 1e-9 * result.timeStep;
  if (t < times.front() - slack || t > times.back() + slack)
    throw std::invalid_argument("t = " + std::to_string(t) + " s lies outside the run (0 to " +
                                std::to_string(times.back()) + " s)");
  const auto next = std::lower_bound(times.begin(), times.end(), t);
  if (next == times.end()) return h.values.back();
  const std::size_t i = std::size_t(next - times.begin());
  if (std::abs(times[i] - t) <= slack || i == 0) return h.values[i];
  if (std::abs(times[i - 1] - t) <= slack) return h.values[i - 1];
  const double s = (t - times[i - 1]) / (times[i] - times[i - 1]);
  return (1 - s) * h.values[i - 1] + s * h.values[i];
}

}  // namespace beamrotor

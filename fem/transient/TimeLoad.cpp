#include "fem/transient/TimeLoad.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace beamrotor::timefn {

TimeFunction constant(double value) {
  return [value](double) { return value; };
}

TimeFunction sine(double amplitude, double omega, double phase) {
  return [=](double t) { return amplitude * std::sin(omega * t + phase); };
}

TimeFunction piecewise(std::vector<TimePiece> pieces) {
  if (pieces.empty()) throw std::invalid_argument("piecewise function of time without pieces");
  for (std::size_t i = 0; i < pieces.size(); ++i) {
    if (!pieces[i].f)
      throw std::invalid_argument("piece " + std::to_string(i) +
                                  " of a piecewise function of "
                                  "time has no function");
    if (i > 0 && !(pieces[i].start > pieces[i - 1].start))
      throw std::invalid_argument(
          "piecewise function of time: piece starts must ascend "
          "strictly (piece " +
          std::to_string(i) + ")");
  }
  return [pieces = std::move(pieces)](double t) {
    // The last piece whose start is <= t.
    const auto next = std::upper_bound(pieces.begin(), pieces.end(), t,
                                       [](double x, const TimePiece& p) { return x < p.start; });
    return next == pieces.begin() ? 0.0 : std::prev(next)->f(t);
  };
}

TimeFunction harmonicSeries(double omega, std::vector<Harmonic> terms, double mean) {
  return [=, terms = std::move(terms)](double t) {
    double sum = mean;
    for (const Harmonic& h : terms) sum += h.amplitude * std::cos(h.k * omega * t + h.phase);
    return sum;
  };
}

TimeFunction tabulated(std::vector<double> times, std::vector<double> values) {
  if (times.empty() || times.size() != values.size())
    throw std::invalid_argument(
        "tabulated function of time: need as many values as times, "
        "at least one");
  for (std::size_t i = 1; i < times.size(); ++i)
    if (!(times[i] > times[i - 1]))
      throw std::invalid_argument(
          "tabulated function of time: times must ascend strictly "
          "(row " +
          std::to_string(i) + ")");
  return [times = std::move(times), values = std::move(values)](double t) {
    if (t <= times.front()) return values.front();
    if (t >= times.back()) return values.back();
    const std::size_t i = std::upper_bound(times.begin(), times.end(), t) - times.begin();
    const double s = (t - times[i - 1]) / (times[i] - times[i - 1]);
    return (1 - s) * values[i - 1] + s * values[i];
  };
}

TimeFunction periodic(TimeFunction g, double period, double start) {
  if (!(period > 0) || !std::isfinite(period))
    throw std::invalid_argument("periodic function of time: the period must be positive");
  if (!g) throw std::invalid_argument("periodic function of time without a function");
  return [g = std::move(g), period, start](double t) {
    double tau = std::fmod(t - start, period);
    if (tau < 0) tau += period;
    if (tau >= period) tau = 0;  // fmod of a tiny negative number can round up to period
    return g(tau);
  };
}

}  // namespace beamrotor::timefn

namespace beamrotor {

TimeLoad pointTimeLoad(const Model& model, const std::string& point, Dof dof, double value,
                       TimeFunction factor, std::string name) {
  TimeLoad load;
  load.name = name.empty() ? point + " " + std::string(dofName(dof)) : std::move(name);
  load.pattern.push_back({model.node(point), dof, value});
  load.factor = std::move(factor);
  return load;
}

}  // namespace beamrotor

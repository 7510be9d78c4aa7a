#include "fem/assembly/MemberEnvelope.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>
#include <tuple>

#include "fem/assembly/ElementExtrema.hpp"
#include "fem/assembly/Polynomial.hpp"
#include "fem/assembly/Recovery.hpp"
#include "fem/model/LineElement.hpp"

namespace beamrotor {

namespace {

const LineElement& lineOf(const Model& model, int e) {
  const LineElement* line = asLine(model.elements().at(e));
  if (!line) throw std::invalid_argument("a member's element is not a line element");
  return *line;
}

/// Places closer than this (fractions of an element's length) are round-off apart: one place.
constexpr double kSame = 1e-12;

/// The largest and smallest value of p over [0, 1]: at an end or where p' vanishes.
std::pair<double, double> rangeOf(const Polynomial& p) {
  ZeroPlaces places{0, 1};
  appendZeros(derivativeOf(p), places);
  double lo = std::numeric_limits<double>::infinity(), hi = -lo;
  for (double s : places) {
    const double v = valueAt(p, s);
    if (std::isnan(v)) return {v, v};
    lo = std::min(lo, v), hi = std::max(hi, v);
  }
  return {lo, hi};
}

/// Where d first turns positive at or after `from`: the start of the first piece of [from, 1]
/// between consecutive zeros of d and of its derivatives (where d keeps one sign) on which d
/// is above `noise`; infinity when it stays at or below it.
double firstRise(const Polynomial& d, double from, double noise) {
  ZeroPlaces knots{from, 1};
  ZeroPlaces zeros;
  appendZeros(d, zeros);
  for (double s : zeros)
    if (s > from && s < 1) knots.push_back(s);
  std::sort(knots.begin(), knots.end());
  for (std::size_t k = 0; k + 1 < knots.size(); ++k)
    if (knots[k + 1] > knots[k] && valueAt(d, 0.5 * (knots[k] + knots[k + 1])) > noise)
      return knots[k];
  return std::numeric_limits<double>::infinity();
}

/// One resultant of every solution on one element, and the range of each over [0, 1].
struct ComponentPolynomials {
  std::vector<Polynomial> p;
  std::vector<std::pair<double, double>> range;  ///< smallest, largest
};

/// The upper envelope of sign p_k (k over the solutions: sign +1 for their largest values, -1
/// for their smallest) over [0, 1]. Appends to `places` the places where the envelope is
/// exact: where the solution on top changes (the envelope's kinks; for the largest values
/// these are its local minima) and the stationary points of the one on top between them (its
/// local maxima and the rest), so every local extremum of the envelope is among them, not only
/// its largest. Returns, ascending, the solutions that can be on top anywhere: those whose
/// largest value reaches the largest of the smallest values (the envelope never drops below
/// it); the others lie below the envelope everywhere and need no evaluation.
std::vector<int> envelopePlaces(const ComponentPolynomials& q, double sign,
                                std::vector<double>& places) {
  const std::size_t n = q.p.size();
  const auto lowest = [&](std::size_t k) { return sign > 0 ? q.range[k].first : -q.range[k].second; };
  const auto highest = [&](std::size_t k) { return sign > 0 ? q.range[k].second : -q.range[k].first; };
  double floor = -std::numeric_limits<double>::infinity(), size = 0;
  for (std::size_t k = 0; k < n; ++k) {
    floor = std::max(floor, lowest(k));
    size = std::max({size, std::abs(lowest(k)), std::abs(highest(k))});
  }
  // Differences below round-off of the values are not crossings: 64 eps of the largest.
  const double noise = 64 * std::numeric_limits<double>::epsilon() * size;
  std::vector<int> candidates;
  for (std::size_t k = 0; k < n; ++k)
    if (!(highest(k) < floor - noise)) candidates.push_back(int(k));  // NaN kept
  if (candidates.empty()) return candidates;
  // The sweep from s = 0: the solution on top, then the nearest place where another rises
  // above it, which becomes the top; a few such changes per element.
  int top = candidates.front();
  for (int k : candidates)
    if (sign * valueAt(q.p[k], 0) > sign * valueAt(q.p[top], 0)) top = k;
  const auto stationaryOfTop = [&](double a, double b) {
    ZeroPlaces zeros;
    appendZeros(derivativeOf(q.p[top]), zeros);
    for (double s : zeros)
      if (s >= a && s <= b) places.push_back(s);
  };
  double s = 0;
  for (std::size_t guard = 0; guard < 4 * candidates.size() + 8; ++guard) {
    double next = std::numeric_limits<double>::infinity();
    int by = -1;
    for (int k : candidates) {
      if (k == top) continue;
      const double rise = firstRise(combination(sign, q.p[k], -sign, q.p[top]), s, noise);
      if (rise < next) next = rise, by = k;
    }
    if (by < 0) break;
    stationaryOfTop(s, next);
    places.push_back(next);
    s = next;
    top = by;
  }
  stationaryOfTop(s, 1);
  return candidates;
}

/// Widens a member's range by one element's (smallest, largest) as memberForceRanges does
/// place by place: the first of equal values kept, a NaN taken on both sides and kept.
void widen(RangeValues& member, const std::pair<double, double>& element) {
  if (std::isnan(element.first)) {
    member.max = member.min = element.first;
    return;
  }
  if (element.second > member.max) member.max = element.second;
  if (element.first < member.min) member.min = element.first;
}

/// Index of the largest (sign +1) or smallest (-1) of the values of one resultant at s over the
/// candidate solutions (ascending: the first of equal values wins), and that value.
std::pair<int, double> extremeAt(const ComponentPolynomials& q, const std::vector<int>& candidates,
                                 double s, double sign) {
  std::pair<int, double> best{-1, 0};
  for (int k : candidates) {
    const double v = valueAt(q.p[k], s);
    if (best.first < 0 || sign * v > sign * best.second || std::isnan(v)) best = {k, v};
    if (std::isnan(v)) break;
  }
  return best;
}

}  // namespace

std::vector<EnvelopeStation> memberEnvelope(const std::vector<LoadedSolution>& solutions,
                                            const std::vector<int>& elements,
                                            int intervalsPerElement,
                                            std::vector<std::array<RangeValues, 6>>* ranges) {
  if (solutions.empty()) throw std::invalid_argument("an envelope needs at least one solution");
  if (ranges) {
    const double inf = std::numeric_limits<double>::infinity();
    ranges->assign(solutions.size(), {});
    for (std::array<RangeValues, 6>& r : *ranges)
      for (RangeValues& v : r) v = {-inf, inf};
  }
  std::vector<EnvelopeStation> out;
  double start = 0;
  std::array<ComponentPolynomials, 6> components;
  for (ComponentPolynomials& q : components) {
    q.p.resize(solutions.size());
    q.range.resize(solutions.size());
  }
  for (int e : elements) {
    // Each solution's six resultants on this element, as polynomials in s, and their ranges.
    for (std::size_t k = 0; k < solutions.size(); ++k) {
      lineOf(*solutions[k].model, e);  // a line element, or a clear error
      const SectionForceSeries series = solutions[k].forceSeries(e);
      for (std::size_t c = 0; c < kForceComponents.size(); ++c) {
        components[c].p[k] = componentPolynomial(series, kForceComponents[c]);
        components[c].range[k] = rangeOf(components[c].p[k]);
        if (ranges) widen((*ranges)[k][c], components[c].range[k]);
      }
    }
    // The places: even ones, and for each resultant those of its upper and lower envelope.
    std::vector<double> places;
    for (int k = 0; k <= intervalsPerElement; ++k) places.push_back(double(k) / intervalsPerElement);
    std::array<std::vector<int>, 6> above, below;
    for (std::size_t c = 0; c < 6; ++c) {
      above[c] = envelopePlaces(components[c], 1, places);
      below[c] = envelopePlaces(components[c], -1, places);
    }
    std::sort(places.begin(), places.end());
    places.erase(std::unique(places.begin(), places.end(),
                             [](double a, double b) { return b - a < kSame; }),
                 places.end());
    const double length = lineOf(*solutions.front().model, e).length();
    for (double s : places) {
      EnvelopeStation st;
      st.element = e;
      st.s = s;
      st.along = start + s * length;
      for (std::size_t c = 0; c < 6; ++c) {
        std::tie(st.maxBy[c], st.max[c]) = extremeAt(components[c], above[c], s, 1);
        std::tie(st.minBy[c], st.min[c]) = extremeAt(components[c], below[c], s, -1);
      }
      out.push_back(st);
    }
    start += length;
  }
  return out;
}

}  // namespace beamrotor

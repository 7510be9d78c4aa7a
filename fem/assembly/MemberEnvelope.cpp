#include "fem/assembly/MemberEnvelope.hpp"

#include <algorithm>
#include <array>
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

/// Places reused from call to call (a fresh ZeroPlaces clears a kilobyte each time; the
/// envelope asks for places millions of times).
using Scratch = std::vector<double>;

/// The largest and smallest value of p over [0, 1]: at an end or where p' vanishes.
std::pair<double, double> rangeOf(const Polynomial& p, Scratch& places) {
  places.assign({0.0, 1.0});
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
double firstRise(const Polynomial& d, double from, double noise, Scratch& knots, Scratch& zeros) {
  knots.assign({from, 1.0});
  zeros.clear();
  appendZeros(d, zeros);
  for (double s : zeros)
    if (s > from && s < 1) knots.push_back(s);
  std::sort(knots.begin(), knots.end());
  for (std::size_t k = 0; k + 1 < knots.size(); ++k)
    if (knots[k + 1] > knots[k] && valueAt(d, 0.5 * (knots[k] + knots[k + 1])) > noise)
      return knots[k];
  return std::numeric_limits<double>::infinity();
}

/// A cubic's coefficients in the Bernstein basis on an interval: the polynomial there is a
/// convex combination of them (Farouki and Rajan, Computer Aided Geometric Design 5, 1988), so
/// it stays between their smallest and largest, and at the ends it equals the first and last.
using Bernstein = std::array<double, 4>;

/// The Bernstein coefficients on [0, 1] of a0 + a1 s + a2 s^2 + a3 s^3 (p's missing
/// coefficients zero); `fits` false when p has a higher degree (no bound is then claimed).
/// Each is within 2 eps sum |a_k| of the exact one (three roundings of terms of at most that).
Bernstein bernsteinOfCubic(const Polynomial& p, bool& fits) {
  fits = p.size() <= 4;
  double a[4] = {0, 0, 0, 0};
  for (std::size_t k = 0; k < p.size() && k < 4; ++k) a[k] = p[k];
  return {a[0], a[0] + a[1] / 3, a[0] + (2 * a[1] + a[2]) / 3, a[0] + a[1] + a[2] + a[3]};
}

/// The Bernstein coefficients of the same cubic on the two parts [0, t] and [t, 1] of its
/// interval (de Casteljau's subdivision): convex combinations of b, each level adding at most
/// 3 eps of max |b_i| to their round-off.
std::pair<Bernstein, Bernstein> splitAt(const Bernstein& b, double t) {
  Bernstein c = b, left, right;
  left[0] = c[0], right[3] = c[3];
  for (int level = 1; level <= 3; ++level) {
    for (int i = 0; i + level <= 3; ++i) c[i] = (1 - t) * c[i] + t * c[i + 1];
    left[level] = c[0], right[3 - level] = c[3 - level];
  }
  return {left, right};
}

/// Whether every Bernstein coefficient of the cubic on its interval, or on each half, quarter
/// (`halvings` deep), is at or below `limit` (false on NaN): then so is the cubic there. The
/// ends are the cubic's own values, so one above the limit ends the search at once.
bool boundedBy(const Bernstein& b, double limit, int halvings) {
  if (!(b[0] <= limit && b[3] <= limit)) return false;
  if (b[1] <= limit && b[2] <= limit) return true;
  if (halvings == 0) return false;
  const auto [left, right] = splitAt(b, 0.5);
  return boundedBy(left, limit, halvings - 1) && boundedBy(right, limit, halvings - 1);
}

/// Halvings of [from, 1] tried before falling back on the zeros of the difference.
constexpr int kHalvings = 2;

/// One resultant of every solution on one element, the range of each over [0, 1], and what
/// bounds each there: its Bernstein coefficients and the sum of its |coefficients| (which
/// bounds the round-off of its value anywhere on [0, 1]).
struct ComponentPolynomials {
  std::vector<Polynomial> p;
  std::vector<std::pair<double, double>> range;  ///< smallest, largest
  std::vector<Bernstein> bernstein;
  std::vector<double> size;  ///< sum |coefficients|; infinity when p is not a cubic
};

/// The computed values of `sign` (p_k - p_top) (firstRise's difference, coefficients rounded,
/// Horner's value) stay at or below `noise` at every place of [from, 1] (a sufficient test:
/// false when it cannot tell). The difference's Bernstein coefficients on [0, 1] are those of
/// p_k less those of p_top, cut to [from, 1] and halved up to kHalvings times. Round-off between
/// them and what firstRise computes, S = sum |coefficients| of p_k and p_top (which bounds every
/// |b_i|): 2 eps S the conversions, 0.5 eps S the subtraction, 0.5 eps S the difference's own
/// coefficients, 6 eps S Horner's value (degree 3), 9 eps S per subdivision (at most 1 +
/// kHalvings): 36 eps S for two halvings, under the 64 eps S kept off the limit (and the noise
/// taken 2 eps low for the rounding of the limit). Relative bounds fail where values underflow:
/// no claim for a tiny S other than 0 (two zero polynomials, whose difference is exactly 0).
bool staysBelow(const ComponentPolynomials& q, int k, int top, double sign, double from,
                double noise) {
  const double size = q.size[k] + q.size[top];
  if (size != 0 && size < 1e-280) return false;
  const double limit = noise * (1 - 2 * std::numeric_limits<double>::epsilon()) -
                       64 * std::numeric_limits<double>::epsilon() * size;
  if (!(limit >= -std::numeric_limits<double>::max())) return false;  // NaN or not finite
  Bernstein d;
  for (std::size_t i = 0; i < d.size(); ++i) d[i] = sign * (q.bernstein[k][i] - q.bernstein[top][i]);
  if (!(d[3] <= limit)) return false;  // above at s = 1: the usual case of a rise
  return boundedBy(from > 0 ? splitAt(d, from).second : d, limit, kHalvings);
}

/// The upper envelope of sign p_k (k over the solutions: sign +1 for their largest values, -1
/// for their smallest) over [0, 1]. Appends to `places` the places where the envelope is
/// exact: where the solution on top changes (the envelope's kinks; for the largest values
/// these are its local minima) and the stationary points of the one on top between them (its
/// local maxima and the rest), so every local extremum of the envelope is among them, not only
/// its largest. Returns, ascending, the solutions that can be on top anywhere: those whose
/// largest value reaches the largest of the smallest values (the envelope never drops below
/// it); the others lie below the envelope everywhere and need no evaluation.
std::vector<int> envelopePlaces(const ComponentPolynomials& q, double sign,
                                std::vector<double>& places, Scratch& knots, Scratch& zeros) {
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
    zeros.clear();
    appendZeros(derivativeOf(q.p[top]), zeros);
    for (double s : zeros)
      if (s >= a && s <= b) places.push_back(s);
  };
  double s = 0;
  for (std::size_t guard = 0; guard < 4 * candidates.size() + 8; ++guard) {
    double next = std::numeric_limits<double>::infinity();
    int by = -1;
    for (int k : candidates) {
      if (k == top || staysBelow(q, k, top, sign, s, noise)) continue;  // no rise: infinity
      const double rise = firstRise(combination(sign, q.p[k], -sign, q.p[top]), s, noise, knots, zeros);
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
  Scratch knots, zeros;
  for (ComponentPolynomials& q : components) {
    q.p.resize(solutions.size());
    q.range.resize(solutions.size());
    q.bernstein.resize(solutions.size());
    q.size.resize(solutions.size());
  }
  for (int e : elements) {
    // Each solution's six resultants on this element, as polynomials in s, and their ranges.
    for (std::size_t k = 0; k < solutions.size(); ++k) {
      lineOf(*solutions[k].model, e);  // a line element, or a clear error
      const SectionForceSeries series = solutions[k].forceSeries(e);
      for (std::size_t c = 0; c < kForceComponents.size(); ++c) {
        ComponentPolynomials& q = components[c];
        q.p[k] = componentPolynomial(series, kForceComponents[c]);
        q.range[k] = rangeOf(q.p[k], knots);
        if (ranges) widen((*ranges)[k][c], q.range[k]);
        bool cubic = true;
        q.bernstein[k] = bernsteinOfCubic(q.p[k], cubic);
        q.size[k] = 0;
        for (double a : q.p[k]) q.size[k] += std::abs(a);
        if (!cubic) q.size[k] = std::numeric_limits<double>::infinity();
      }
    }
    // The places: even ones, and for each resultant those of its upper and lower envelope.
    std::vector<double> places;
    for (int k = 0; k <= intervalsPerElement; ++k) places.push_back(double(k) / intervalsPerElement);
    std::array<std::vector<int>, 6> above, below;
    for (std::size_t c = 0; c < 6; ++c) {
      above[c] = envelopePlaces(components[c], 1, places, knots, zeros);
      below[c] = envelopePlaces(components[c], -1, places, knots, zeros);
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

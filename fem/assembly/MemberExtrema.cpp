#include "fem/assembly/MemberExtrema.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <optional>
#include <stdexcept>

#include "fem/assembly/ElementExtrema.hpp"
#include "fem/assembly/Polynomial.hpp"
#include "fem/assembly/Recovery.hpp"
#include "fem/assembly/SolutionPolynomials.hpp"

namespace beamrotor {

namespace {

/// The largest of sqrt(P(s)) over [0, 1] for a polynomial P >= 0: at an end or where P' = 0.
std::pair<double, double> largestRoot(const Polynomial& P) {
  ZeroPlaces places{0, 1};
  appendZeros(derivativeOf(P), places);
  std::pair<double, double> best{0, -std::numeric_limits<double>::infinity()};
  for (double s : places) {
    const double v = std::sqrt(std::max(0.0, valueAt(P, s)));
    if (std::isnan(valueAt(P, s))) return {s, std::numeric_limits<double>::quiet_NaN()};
    if (v > best.second) best = {s, v};
  }
  return best;
}

const LineElement& lineElement(const Model& model, int e) {
  const LineElement* line = asLine(model.elements().at(e));
  if (!line) throw std::invalid_argument("element " + std::to_string(e) + " is not a beam");
  return *line;
}

/// A value at fraction s of element e, `along` m from its member's start.
MemberValue memberValue(const Model& model, int e, double s, double along, double value) {
  return {e, s, along, value, placeOnElement(model, e, s)};
}

}  // namespace

const char* componentName(ForceComponent c) {
  static constexpr std::array<const char*, 6> names{"N", "Vy", "Vz", "T", "My", "Mz"};
  return names[int(c)];
}

double componentOf(const SectionForces& f, ForceComponent c) {
  switch (c) {
    case ForceComponent::N:
      return f.N;
    case ForceComponent::Vy:
      return f.Vy;
    case ForceComponent::Vz:
      return f.Vz;
    case ForceComponent::T:
      return f.T;
    case ForceComponent::My:
      return f.My;
    default:
      return f.Mz;
  }
}

Eigen::Vector3d placeOnElement(const Model& model, int element, double s) {
  const auto [a, b] = lineElement(model, element).endNodes();
  return (1 - s) * model.nodes()[a] + s * model.nodes()[b];
}

std::optional<std::pair<int, double>> memberLocation(const Model& model, int element, double s) {
  for (std::size_t m = 0; m < model.members().size(); ++m) {
    double start = 0;
    for (int e : model.members()[m].second) {
      const double length = lineElement(model, e).length();
      if (e == element) return std::pair{int(m), start + s * length};
      start += length;
    }
  }
  return std::nullopt;
}

Polynomial componentPolynomial(const SectionForceSeries& series, ForceComponent c) {
  Polynomial p;
  for (const SectionForces& coefficient : series.c) p.push_back(componentOf(coefficient, c));
  return p;
}

std::array<ComponentRange, 6> memberForceRanges(const LoadedSolution& solution,
                                                const std::vector<int>& elements) {
  const Model& model = *solution.model;
  std::array<ComponentRange, 6> out;
  const double inf = std::numeric_limits<double>::infinity();
  for (ComponentRange& r : out) r.max.value = -inf, r.min.value = inf;
  double start = 0;
  for (int e : elements) {
    const LineElement& line = lineElement(model, e);
    const SectionForceSeries series = solution.forceSeries(e);
    for (std::size_t c = 0; c < kForceComponents.size(); ++c) {
      const ForceComponent component = kForceComponents[c];
      const Polynomial p = componentPolynomial(series, component);
      // A polynomial's extremes: the ends and the zeros of its derivative.
      ZeroPlaces places{0, 1};
      appendZeros(derivativeOf(p), places);
      for (double s : places) {
        const double v = valueAt(p, s);
        const bool nan = std::isnan(v), above = v > out[c].max.value, below = v < out[c].min.value;
        if (!nan && !above && !below) continue;  // the place is not needed
        const MemberValue here = memberValue(model, e, s, start + s * line.length(), v);
        if (nan) out[c].max = out[c].min = here;
        if (above) out[c].max = here;
        if (below) out[c].min = here;
      }
    }
    start += line.length();
  }
  return out;
}

MemberValue largestChordDeflection(const LoadedSolution& solution,
                                   const std::vector<int>& elements) {
  const Model& model = *solution.model;
  if (elements.empty()) throw std::invalid_argument("a member needs at least one element");
  const LineElement& first = lineElement(model, elements.front());
  const LineElement& last = lineElement(model, elements.back());
  const Eigen::Vector3d x0 = model.nodes()[first.endNodes()[0]];
  const Eigen::Vector3d chord = model.nodes()[last.endNodes()[1]] - x0;
  const double length = chord.norm();
  const Eigen::Vector3d axis = chord / length;
  const auto endTranslation = [&](int element, double s) {
    const std::array<Polynomial, 3> u = solution.translationSeries(element);
    return Eigen::Vector3d(valueAt(u[0], s), valueAt(u[1], s), valueAt(u[2], s));
  };
  const Eigen::Vector3d u0 = endTranslation(elements.front(), 0);
  const Eigen::Vector3d u1 = endTranslation(elements.back(), 1);

  // Each element's squared distance from the chord as a polynomial, with an upper bound of
  // the distance (from Bernstein bounds, a margin above their round-off included) and its
  // value at the middle.
  struct Piece {
    int element;
    double start, length;
    Polynomial squared;
    double bound;
  };
  std::vector<Piece> pieces;
  double seed = -std::numeric_limits<double>::infinity();
  double start = 0;
  for (int e : elements) {
    const LineElement& line = lineElement(model, e);
    // Member fraction t = t0 + s dt along this element; chord displacement linear in t.
    const double t0 = (model.nodes()[line.endNodes()[0]] - x0).dot(axis) / length;
    const double dt = line.length() / length;
    const std::array<Polynomial, 3> u = solution.translationSeries(e);
    std::array<Polynomial, 3> deviation;
    double boundSquared = 0;
    for (int c = 0; c < 3; ++c) {
      const Polynomial chordPart{u0[c] + t0 * (u1[c] - u0[c]), dt * (u1[c] - u0[c])};
      deviation[c] = combination(1, u[c], -1, chordPart);
      boundSquared += std::pow(boundOnUnitInterval(deviation[c]), 2);
    }
    // Across the chord: remove the part along its original direction.
    Polynomial along;
    for (int c = 0; c < 3; ++c) along = combination(1, along, axis[c], deviation[c]);
    Polynomial squared = combination(-1, productOf(along, along), 0, {});
    for (int c = 0; c < 3; ++c) squared = combination(1, squared, 1, productOf(deviation[c], deviation[c]));
    seed = std::max(seed, std::sqrt(std::max(0.0, valueAt(squared, 0.5))));
    // Two bounds of the distance, the smaller kept: the components' (which include the
    // deviation along the chord) and the square root of the squared distance's own Bernstein
    // bound (without that part, so much the smaller for a member whose ends move along it).
    // The second's polynomial is a difference of squares that may cancel: its values carry
    // round-off of up to 20 eps sum |c_k| (Horner, degree 10), added with a wide margin.
    double size = 0;
    for (double c : squared) size += std::abs(c);
    const double bound =
        std::min(std::sqrt(boundSquared) * (1 + 1e-9),
                 std::sqrt((boundOnUnitInterval(squared) + 1e-12 * size) * (1 + 1e-9)));
    pieces.push_back({e, start, line.length(), squared, bound});
    start += line.length();
  }
  // The exact largest on every element that can hold the member's largest: an element whose
  // bound is below a value reached elsewhere (with a margin far above the bound's round-off)
  // cannot, and is skipped; the others, in order, keep the first of equal values.
  MemberValue best{elements.front(), 0, 0, -std::numeric_limits<double>::infinity()};
  for (const Piece& piece : pieces) {
    if (piece.bound < seed) continue;
    const auto [s, value] = largestRoot(piece.squared);
    if (std::isnan(value) || value > best.value)
      best = memberValue(model, piece.element, s, piece.start + s * piece.length, value);
    if (std::isnan(value)) return best;
  }
  return best;
}

MemberValue largestDisplacement(const LoadedSolution& solution) {
  const Model& model = *solution.model;
  const NodalField& displacement = *solution.displacement;
  MemberValue best{-1, 0, 0, -std::numeric_limits<double>::infinity()};
  for (int n = 0; n < model.nodeCount(); ++n) {
    const double v = std::sqrt(std::pow(displacement(n, 0), 2) + std::pow(displacement(n, 1), 2) +
                               std::pow(displacement(n, 2), 2));
    if (std::isnan(v) || v > best.value) best = {-1, double(n), 0, v, model.nodes()[n]};
    if (std::isnan(v)) return best;
  }
  for (int e = 0; e < int(model.elements().size()); ++e) {
    const LineElement* line = asLine(model.elements()[e]);
    if (!line) continue;
    // An element whose translations' Bernstein bounds stay below the largest so far (with a
    // margin far above their round-off) cannot hold a larger one: skipped. The bounds of the
    // solution's polynomials when it carries them (of a combination, its cases' weighted: its
    // translations are then summed only where needed).
    std::optional<std::array<Polynomial, 3>> u;
    std::array<double, 3> bounds;
    if (solution.polynomials) {
      bounds = solution.polynomials->bounds(e).translations;
    } else {
      u = solution.translationSeries(e);
      for (int c = 0; c < 3; ++c) bounds[c] = boundOnUnitInterval((*u)[c]);
    }
    double boundSquared = 0;
    for (int c = 0; c < 3; ++c) boundSquared += std::pow(bounds[c], 2);
    if (std::sqrt(boundSquared) * (1 + 1e-9) < best.value) continue;
    if (!u) u = solution.translationSeries(e);
    Polynomial squared;
    for (int c = 0; c < 3; ++c) squared = combination(1, squared, 1, productOf((*u)[c], (*u)[c]));
    const auto [s, value] = largestRoot(squared);
    if (std::isnan(value) || value > best.value)
      best = memberValue(model, e, s, s * line->length(), value);
    if (std::isnan(value)) return best;
  }
  return best;
}

}  // namespace beamrotor

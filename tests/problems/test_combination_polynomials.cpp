// A load combination's polynomials along the elements, the factored sum of its cases' (fem/
// assembly/SolutionPolynomials.hpp), against two independent references: the polynomials
// recovered element by element from the combination's own nodal field and loading (the path
// every combination took before), and a deck carrying the combination's factored loads solved
// on its own. And the envelope over the combinations along a member, exact at every local
// extreme (a second peak inside an element as well as the largest) and one polynomial between
// its places, against a dense sampling of every combination.
#include <doctest/doctest.h>

#include <algorithm>
#include <cstdlib>
#include <cmath>
#include <sstream>
#include <string>
#include <vector>

#include "fem/assembly/ElementExtrema.hpp"
#include "fem/assembly/MemberEnvelope.hpp"
#include "fem/assembly/MemberExtrema.hpp"
#include "fem/assembly/Recovery.hpp"
#include "fem/assembly/SolutionPolynomials.hpp"
#include "problems/output/PreparedRun.hpp"
#include "problems/output/structure/CaseEnvelope.hpp"
#include "problems/output/structure/CombinationHull.hpp"
#include "problems/output/structure/LineSampling.hpp"
#include "problems/output/structure/MemberOutput.hpp"
#include "problems/output/structure/StaticExtremes.hpp"
#include "problems/run/Study.hpp"
#include "tests/problems/DeckTestSupport.hpp"

using namespace beamrotor;

// Named, not anonymous: the test sources are compiled in unity batches.
namespace combination_polynomials {

/// A 3d portal (tube columns, a rectangular beam) with an out-of-plane cantilever, under
/// self-weight and a trapezoidal load (dead), a point load and a uniform load across a column
/// (wind) and a temperature gradient (heat), or, with `loads`, those loads alone.
std::string frameDeck(const std::string& loads) {
  return "model: {dimension: 3d}\n"
         "materials: [{name: steel, E: 210e9, nu: 0.3, rho: 7850, alpha: 12e-6}]\n"
         "sections:\n"
         "  - {name: column, shape: tube, D: 0.3, t: 0.012}\n"
         "  - {name: beam, shape: rectangle, b: 0.2, h: 0.4}\n"
         "nodes: [{name: A, at: [0, 0, 0]}, {name: B, at: [0, 3.5, 0]}, {name: C, at: [4, 3.5, 0]},\n"
         "        {name: D, at: [4, 0, 0]}, {name: E, at: [4, 3.5, 2.5]}]\n"
         "members:\n"
         "  - {name: left, from: A, to: B, section: column, elements: 3}\n"
         "  - {name: beam, from: B, to: C, section: beam, elements: 4}\n"
         "  - {name: right, from: D, to: C, section: column, elements: 3}\n"
         "  - {name: arm, from: C, to: E, section: beam, elements: 2}\n"
         "supports: [{name: A, at: A, fix: clamped}, {name: D, at: D, fix: clamped}]\n" +
         loads + "analyses: [{type: static}]\n";
}

const std::string kDead = "{type: self-weight, g: 9.81}, "
                          "{type: distributed, member: beam, qy: [-10e3, -25e3]}";
const std::string kWind = "{type: point, at: B, fx: 8e3}, "
                          "{type: distributed, member: left, qz: 3e3}";
const std::string kHeat = "{type: temperature, member: beam, dT: 20, dT_y: 15}";

/// The three cases, then the `combinations:` key with its list still to write.
const std::string kCaseList = "loads: []\n"
                              "load_cases:\n"
                              "  - {name: dead, loads: [" + kDead + "]}\n"
                              "  - {name: wind, loads: [" + kWind + "]}\n"
                              "  - {name: heat, loads: [" + kHeat + "]}\n"
                              "combinations:\n";

const std::string kCases = kCaseList +
                           "  - {name: ULS, factors: {dead: 1.35, wind: 1.5, heat: 0.6}}\n"
                           "  - {name: suction, factors: {dead: 1, wind: -1.5}}\n"
                           "  - {name: cold, factors: {dead: 1, heat: -1.2}}\n";

/// The largest |value| of `values`.
double largestOf(const std::vector<double>& values) {
  double m = 0;
  for (double v : values) m = std::max(m, std::abs(v));
  return m;
}

/// Every extreme a combination reports (element peaks, member ranges, chord deflections, the
/// largest displacement), in one order, each with its kind (what it measures), for comparing
/// two ways of computing them.
struct Extreme {
  int kind;
  double value;
};
std::vector<Extreme> extremesOf(const LoadedSolution& solution) {
  std::vector<Extreme> out;
  for (const ElementPeaks& p : elementPeaks(solution))
    out.insert(out.end(), {{0, p.stress.value}, {1, p.shear.value}, {2, p.moment.value}});
  for (const auto& [name, elements] : solution.model->members()) {
    const auto ranges = memberForceRanges(solution, elements);
    for (int c = 0; c < 6; ++c) out.insert(out.end(), {{3 + c, ranges[c].max.value}, {3 + c, ranges[c].min.value}});
    out.push_back({9, largestChordDeflection(solution, elements).value});
  }
  out.push_back({10, largestDisplacement(solution).value});
  return out;
}

/// Checks that a and b (the same extremes two ways) agree to 1e-12 of the largest value of
/// each kind: an extreme much smaller than others of its kind (a resultant a member barely
/// carries) holds the round-off of their size, from the cancellation that leaves it small
/// (measured up to 1.1e-13 of it here: the element recovery in local frames against the sum).
void checkSameExtremes(const std::vector<Extreme>& a, const std::vector<Extreme>& b) {
  REQUIRE(a.size() == b.size());
  std::vector<double> scale(11, 0.0);
  for (const Extreme& x : b) scale[x.kind] = std::max(scale[x.kind], std::abs(x.value));
  double largest = 0;
  for (std::size_t i = 0; i < a.size(); ++i) {
    CAPTURE(a[i].kind);
    REQUIRE(a[i].kind == b[i].kind);
    CHECK(std::abs(a[i].value - b[i].value) <= 1e-12 * scale[b[i].kind]);
    largest = std::max(largest, std::abs(a[i].value - b[i].value) / scale[b[i].kind]);
  }
  MESSAGE("extremes agree to " << largest << " of the largest of their kind");
}

const CaseOutcome& combinationNamed(const RunResult& run, const std::string& name) {
  for (const CaseOutcome& c : casesOf(run.analyses.front()))
    if (c.name == name) return c;
  FAIL("no combination " << name);
  throw;
}

// A simply supported beam of one element under two triangular loads: rising to the right
// (moment (q L x / 6)(1 - x^2 / L^2), largest at x = L / sqrt(3)) and falling (its mirror).
// Combination R (rising) and F (0.98 falling) each have one peak; the envelope of the largest
// moments has two inside the one element, F's at 0.4226 L and R's, the larger, at 0.5774 L,
// with the change from F to R between them; `both` (uniform 0.4 q) is never on top.
const std::string kTwoPeaks =
    "model: {dimension: planar}\n"
    "materials: [{name: steel, E: 210e9, nu: 0.3}]\n"
    "sections: [{name: beam, shape: general, A: 53.8e-4, I: 8356e-8, J: 1e-6, depth: 0.3, "
    "width: 0.15}]\n"
    "nodes: [{name: A, at: [0, 0]}, {name: B, at: [6, 0]}]\n"
    "members: [{name: beam, from: A, to: B, section: beam, elements: 1}]\n"
    "supports: [{name: A, at: A, fix: pinned}, {name: B, at: B, fix: [uy]}]\n"
    "loads: []\n"
    "load_cases:\n"
    "  - {name: rising, loads: [{type: distributed, member: beam, qy: [0, -30e3]}]}\n"
    "  - {name: falling, loads: [{type: distributed, member: beam, qy: [-30e3, 0]}]}\n"
    "combinations:\n"
    "  - {name: R, factors: {rising: 1}}\n"
    "  - {name: F, factors: {falling: 0.98}}\n"
    "  - {name: both, factors: {rising: 0.4, falling: 0.4}}\n"
    "analyses: [{type: static}]\n";

/// The portal under 46 combinations whose curves cross, meet and tie on every element: a
/// grid of factors (their curves cross), fans dead + w wind and 1.35 dead + h heat (every
/// curve of a fan passes through the places where the fanned case's resultant is zero: many
/// curves meeting at one point), the same factors twice (exactly equal curves), and pairs
/// that differ only in a case that is zero or round-off on an element (the arm is a
/// cantilever that only the dead load bends, so on it wind and heat add nothing but
/// round-off).
std::string crossingDeck() {
  std::string deck = kCaseList;
  int count = 0;
  const auto add = [&](double dead, double wind, double heat) {
    std::ostringstream line;
    line.precision(17);
    line << "  - {name: C" << count++ << ", factors: {dead: " << dead << ", wind: " << wind
         << ", heat: " << heat << "}}\n";
    deck += line.str();
  };
  for (double dead : {1.0, 1.35})
    for (double wind : {-1.5, -0.75, 0.0, 0.75, 1.5})
      for (double heat : {-1.2, 0.0, 0.6}) add(dead, wind, heat);
  for (double wind : {-1.5, -1.0, -0.5, 0.5, 1.0, 1.5}) add(1, wind, 0);  // a fan
  for (double heat : {-0.6, 0.3, 1.2}) add(1.35, 0, heat);                 // another
  add(1, 0.75, 0), add(1.35, -1.5, 0.6), add(1, 0, 0);                      // equal to earlier
  add(1.35, 1.5, -1.2), add(1.35, 1.5, -1.2);                               // two more of one
  add(1, 0, 1e-3), add(1, 1e-3, 0);  // equal to 1 dead on the arm but for round-off
  return frameDeck(deck);
}

/// The envelope of `solutions` along `elements` with each solution's ranges of the
/// resultants into `ranges`, checked to be the envelope computed without them: the same
/// places, values and solutions named, to the bit.
std::vector<EnvelopeStation> envelopeWithRanges(const std::vector<LoadedSolution>& solutions,
                                                const std::vector<int>& elements,
                                                std::vector<std::array<RangeValues, 6>>& ranges) {
  std::vector<EnvelopeStation> with =
      memberEnvelope(solutions, elements, kIntervalsPerElement, &ranges);
  const std::vector<EnvelopeStation> without =
      memberEnvelope(solutions, elements, kIntervalsPerElement);
  REQUIRE(with.size() == without.size());
  for (std::size_t i = 0; i < with.size(); ++i) {
    CHECK(with[i].s == without[i].s);
    CHECK(with[i].max == without[i].max);
    CHECK(with[i].maxBy == without[i].maxBy);
    CHECK(with[i].min == without[i].min);
    CHECK(with[i].minBy == without[i].minBy);
  }
  return with;
}

/// Resultant c (kForceComponents order) of `solution` on element e, as the envelope reads it.
Polynomial resultantOn(const LoadedSolution& solution, int e, std::size_t c) {
  return componentPolynomial(solution.forceSeries(e), kForceComponents[c]);
}

/// The largest |value| of resultant c of any of `solutions` on `elements` (101 places each).
double resultantScale(const std::vector<LoadedSolution>& solutions,
                      const std::vector<int>& elements, std::size_t c) {
  double scale = 0;
  for (int e : elements)
    for (const LoadedSolution& solution : solutions)
      for (int j = 0; j <= 100; ++j)
        scale = std::max(scale, std::abs(valueAt(resultantOn(solution, e, c), j / 100.0)));
  return scale;
}

/// Checks that between consecutive stations of an element each side of the envelope `env` of
/// resultant c is one of `solutions`' polynomials (the one on top at the middle): on a fine
/// grid none is above (below) it, and it meets the stations' values at the ends, to roundOff.
void checkOnePolynomialBetween(const std::vector<EnvelopeStation>& env,
                               const std::vector<LoadedSolution>& solutions, std::size_t c,
                               double roundOff) {
  const std::size_t n = solutions.size();
  for (std::size_t i = 0; i + 1 < env.size(); ++i) {
    if (env[i].element != env[i + 1].element) continue;
    const int e = env[i].element;
    const double a = env[i].s, b = env[i + 1].s, mid = 0.5 * (a + b);
    for (double sign : {1.0, -1.0}) {
      std::size_t top = 0;
      for (std::size_t k = 1; k < n; ++k)
        if (sign * valueAt(resultantOn(solutions[k], e, c), mid) >
            sign * valueAt(resultantOn(solutions[top], e, c), mid))
          top = k;
      const Polynomial t = resultantOn(solutions[top], e, c);
      CHECK(std::abs(valueAt(t, a) - (sign > 0 ? env[i].max[c] : env[i].min[c])) <= roundOff);
      CHECK(std::abs(valueAt(t, b) - (sign > 0 ? env[i + 1].max[c] : env[i + 1].min[c])) <=
            roundOff);
      for (int j = 0; j <= 50; ++j) {
        const double x = a + (b - a) * j / 50;
        for (std::size_t k = 0; k < n; ++k)
          CHECK(sign * valueAt(resultantOn(solutions[k], e, c), x) <= sign * valueAt(t, x) + roundOff);
      }
    }
  }
}

}  // namespace combination_polynomials

using namespace combination_polynomials;

TEST_SUITE("load cases") {
  TEST_CASE("a combination's polynomials: its cases' factored sum, as recovered and as solved") {
    const Study s = test::solveDeckText(frameDeck(kCases), "frame_cases.yaml");
    const RunResult& run = *s.run;
    const Model& model = *run.model;
    for (const CaseOutcome& c : casesOf(run.analyses.front())) {
      CAPTURE(c.name);
      REQUIRE(c.polynomials);
      const LoadedSolution superposed = c.on(model);
      const LoadedSolution recovered{model, c.statics.displacement, c.loading.get()};
      // Coefficient by coefficient: the sum of the cases' recovered polynomials against the
      // combination's own, both from fields that agree to round-off (the combination's field
      // is the factored sum of the cases'): a few ulps of the largest coefficient, 1e-12
      // leaves room for the cancellation inside the element recovery (measured below 1e-14).
      std::vector<double> a, b;
      for (int e = 0; e < int(model.elements().size()); ++e) {
        if (!asLine(model.elements()[e])) continue;
        const SectionForceSeries fa = superposed.forceSeries(e), fb = recovered.forceSeries(e);
        for (std::size_t k = 0; k < 4; ++k)
          for (ForceComponent f : kForceComponents) {
            a.push_back(componentOf(fa.c[k], f));
            b.push_back(componentOf(fb.c[k], f));
          }
      }
      const double forceScale = largestOf(b);
      REQUIRE(forceScale > 0);
      for (std::size_t i = 0; i < a.size(); ++i) CHECK(std::abs(a[i] - b[i]) <= 1e-12 * forceScale);
      a.clear(), b.clear();
      for (int e = 0; e < int(model.elements().size()); ++e) {
        if (!asLine(model.elements()[e])) continue;
        const auto ua = superposed.translationSeries(e), ub = recovered.translationSeries(e);
        for (int k = 0; k < 3; ++k) {
          a.insert(a.end(), ua[k].begin(), ua[k].end());
          b.insert(b.end(), ub[k].begin(), ub[k].end());
        }
      }
      const double displacementScale = largestOf(b);
      REQUIRE(displacementScale > 0);
      for (std::size_t i = 0; i < a.size(); ++i)
        CHECK(std::abs(a[i] - b[i]) <= 1e-12 * displacementScale);
      // Every extreme (found from those coefficients; a peak's place may move by the square
      // root of round-off where it is flat, its value by round-off only).
      checkSameExtremes(extremesOf(superposed), extremesOf(recovered));
    }
    // The ULS combination against its factored loads solved as a deck of their own (one
    // factorisation each; the solutions' round-off, about 1e-15 of the displacements here,
    // bounds the difference). Its loads: dead x 1.35, wind x 1.5, heat x 0.6.
    const std::string uls =
        "loads: [{type: self-weight, g: 13.2435}, "
        "{type: distributed, member: beam, qy: [-13.5e3, -33.75e3]}, "
        "{type: point, at: B, fx: 12e3}, {type: distributed, member: left, qz: 4.5e3}, "
        "{type: temperature, member: beam, dT: 12, dT_y: 9}]\n";
    const Study direct = test::solveDeckText(frameDeck(uls), "frame_uls.yaml");
    const Model& directModel = *direct.run->model;
    const LoadedSolution alone{directModel, staticsOf(direct.run->analyses.front())->displacement};
    checkSameExtremes(extremesOf(combinationNamed(run, "ULS").on(model)), extremesOf(alone));
  }

  TEST_CASE("a combination's bounds from its cases': above every value, above its own bounds") {
    // SolutionPolynomials::bounds of a combination weights its cases' Bernstein bounds by
    // |factor|: at least the largest |value| of each resultant and translation along every
    // element (101 places), and at least the Bernstein bound of its own summed polynomials
    // (the triangle inequality on the Bernstein coefficients), by at most round-off.
    const Study s = test::solveDeckText(crossingDeck(), "frame_bounds.yaml");
    const Model& model = *s.run->model;
    std::size_t tight = 0, checked = 0;
    for (const CaseOutcome& c : casesOf(s.run->analyses.front())) {
      if (!c.combination) continue;
      SolutionPolynomials summed;
      c.polynomials->sumInto(summed);
      for (int e = 0; e < int(model.elements().size()); ++e) {
        const ElementBounds weighted = c.polynomials->bounds(e), own = summed.bounds(e);
        const SectionForceSeries forces = c.on(model).forceSeries(e);
        const std::array<Polynomial, 3> u = c.on(model).translationSeries(e);
        const double forceScale = 1e-12 * (1 + weighted.forces.N + weighted.forces.My + weighted.forces.Mz);
        for (double SectionForces::*f : {&SectionForces::N, &SectionForces::Vy, &SectionForces::Vz,
                                         &SectionForces::T, &SectionForces::My, &SectionForces::Mz}) {
          for (int j = 0; j <= 100; ++j)
            CHECK(std::abs(forces.at(j / 100.0).*f) <= weighted.forces.*f + forceScale);
          CHECK(own.forces.*f <= weighted.forces.*f + forceScale);
          tight += own.forces.*f == weighted.forces.*f;
          ++checked;
        }
        for (int k = 0; k < 3; ++k) {
          const double scale = 1e-12 * (1e-9 + weighted.translations[k]);
          for (int j = 0; j <= 100; ++j)
            CHECK(std::abs(valueAt(u[k], j / 100.0)) <= weighted.translations[k] + scale);
          CHECK(own.translations[k] <= weighted.translations[k] + scale);
        }
      }
    }
    MESSAGE(tight << " of " << checked << " resultant bounds equal to the sum's own");
    CHECK(checked == 46 * 12 * 6);
  }

  TEST_CASE("the envelope along an element: every local extreme exact, one polynomial between") {
    const Study s = test::solveDeckText(kTwoPeaks, "two_peaks.yaml");
    const RunResult& run = *s.run;
    const Model& model = *run.model;
    std::vector<LoadedSolution> combinations;
    for (const CaseOutcome& c : casesOf(run.analyses.front()))
      if (c.combination) combinations.push_back(c.on(model));
    REQUIRE(combinations.size() == 3);
    const std::vector<int>& elements = model.members().front().second;
    REQUIRE(elements.size() == 1);
    // Only the element's ends as even places: everything inside comes from the envelope.
    const std::vector<EnvelopeStation> env = memberEnvelope(combinations, elements, 1);
    const auto mz = [&](std::size_t k, double s) {
      return combinations[k].forceSeries(elements.front()).at(s).Mz;
    };
    const double q = 30e3, L = 6, scale = q * L * L;
    // Round-off of the moments: a few ulps of q L^2; 1e-13 of it.
    const double roundOff = 1e-13 * scale;
    // 1. Both peaks are stations, at their closed-form places and values.
    const double xi = 1 / std::sqrt(3.0), peak = q * L * L * xi * (1 - xi * xi) / 6;
    const auto stationNear = [&](double s) -> const EnvelopeStation* {
      for (const EnvelopeStation& st : env)
        if (std::abs(st.s - s) < 1e-9) return &st;
      return nullptr;
    };
    const EnvelopeStation* right = stationNear(xi);
    const EnvelopeStation* left = stationNear(1 - xi);
    REQUIRE(right);
    REQUIRE(left);
    // The sagging side: the largest values if the moments of a downward load are positive in
    // the element's sign convention, the smallest otherwise; R governs the right peak, F the
    // left one.
    const double sagging = right->max[5] > -right->min[5] ? 1 : -1;
    const auto side = [&](const EnvelopeStation* st) {
      return sagging > 0 ? std::pair{st->max[5], st->maxBy[5]} : std::pair{-st->min[5], st->minBy[5]};
    };
    CHECK(std::abs(side(right).first - peak) <= roundOff);
    CHECK(side(right).second == 0);
    CHECK(std::abs(side(left).first - 0.98 * peak) <= roundOff);
    CHECK(side(left).second == 1);
    // 2. Between consecutive stations the envelope is one combination's polynomial (the one on
    //    top at the middle), so nothing between them is larger or smaller than it, and neither
    //    envelope has a local extreme there: dense sampling, 2000 places per piece.
    for (std::size_t i = 0; i + 1 < env.size(); ++i) {
      const double a = env[i].s, b = env[i + 1].s, mid = 0.5 * (a + b);
      for (double sign : {1.0, -1.0}) {
        std::size_t top = 0;
        for (std::size_t k = 1; k < combinations.size(); ++k)
          if (sign * mz(k, mid) > sign * mz(top, mid)) top = k;
        for (int j = 0; j <= 2000; ++j) {
          const double t = a + (b - a) * j / 2000;
          double best = mz(0, t);
          for (std::size_t k = 1; k < combinations.size(); ++k)
            best = sign > 0 ? std::max(best, mz(k, t)) : std::min(best, mz(k, t));
          CHECK(std::abs(best - mz(top, t)) <= roundOff);
        }
      }
    }
    // 3. At every station, the envelope's values and names are those of the combinations
    //    evaluated there.
    for (const EnvelopeStation& st : env) {
      double hi = -1e300, lo = 1e300;
      for (std::size_t k = 0; k < combinations.size(); ++k)
        hi = std::max(hi, mz(k, st.s)), lo = std::min(lo, mz(k, st.s));
      CHECK(std::abs(st.max[5] - hi) <= roundOff);
      CHECK(std::abs(st.min[5] - lo) <= roundOff);
      CHECK(std::abs(mz(std::size_t(st.maxBy[5]), st.s) - hi) <= roundOff);
      CHECK(std::abs(mz(std::size_t(st.minBy[5]), st.s) - lo) <= roundOff);
    }
  }

  TEST_CASE("a combination's extremes: sums taken once, peaks of the elements that can govern") {
    // The portal under twelve combinations whose factors step through the three cases, so
    // that different elements govern different combinations.
    std::string deck = kCaseList;
    for (int k = 0; k < 12; ++k)
      deck += "  - {name: C" + std::to_string(k) + ", factors: {dead: " +
              std::to_string(1 + 0.05 * (k % 8)) + ", wind: " + std::to_string(-1.5 + 0.25 * k) +
              ", heat: " + std::to_string(0.6 - 0.1 * k) + "}}\n";
    const Study s = test::solveDeckText(frameDeck(deck), "frame_twelve.yaml");
    const RunResult& run = *s.run;
    const Model& model = *run.model;
    std::size_t kept = 0, all = 0;
    SolutionPolynomials summed;
    for (const CaseOutcome& c : casesOf(run.analyses.front())) {
      CAPTURE(c.name);
      REQUIRE(c.polynomials);
      const LoadedSolution direct = c.on(model);  // each read a factored sum
      LoadedSolution once = direct;
      c.polynomials->sumInto(summed);
      once.polynomials = &summed;
      // 1. The sums taken once are the same bits as the sums taken on every read.
      for (int e = 0; e < int(model.elements().size()); ++e) {
        if (!asLine(model.elements()[e])) continue;
        const SectionForceSeries fa = once.forceSeries(e), fb = direct.forceSeries(e);
        for (std::size_t k = 0; k < 4; ++k)
          for (ForceComponent f : kForceComponents)
            CHECK(componentOf(fa.c[k], f) == componentOf(fb.c[k], f));
        const auto ua = once.translationSeries(e), ub = direct.translationSeries(e);
        for (int k = 0; k < 3; ++k)
          CHECK(std::equal(ua[k].begin(), ua[k].end(), ub[k].begin(), ub[k].end()));
      }
      // 2. The peaks of the elements that can govern against every element's: each kept
      //    element's peaks are its own, and the largest of each kind is the same element,
      //    place and value, to the bit.
      const std::vector<ElementPeaks> every = elementPeaks(direct);
      const std::vector<ElementPeaks> governing = peaksThatCanGovern(once);
      REQUIRE(!governing.empty());
      for (const ElementPeaks& g : governing) {
        const auto same = std::find_if(every.begin(), every.end(), [&](const ElementPeaks& p) {
          return p.stress.element == g.stress.element;
        });
        REQUIRE(same != every.end());
        for (BeamPeak ElementPeaks::*kind : {&ElementPeaks::stress, &ElementPeaks::shear, &ElementPeaks::moment})
          CHECK(((*same).*kind).value == (g.*kind).value);
      }
      for (BeamPeak ElementPeaks::*kind : {&ElementPeaks::stress, &ElementPeaks::shear, &ElementPeaks::moment}) {
        const auto a = largestPeak(governing, kind), b = largestPeak(every, kind);
        REQUIRE(a);
        REQUIRE(b);
        CHECK(a->element == b->element);
        CHECK(a->s == b->s);
        CHECK(a->value == b->value);
      }
      kept += governing.size();
      all += every.size();
    }
    // The bound leaves elements out (else the test above would compare a list with itself).
    MESSAGE("peaks computed on " << kept << " of " << all << " elements");
    CHECK(kept < all);
  }

  TEST_CASE("many combinations' extremes and envelope split over cores: the bits of one by one") {
    // The portal with 90 elements a member under 300 combinations: 303 solutions x 360
    // elements make two parts (one per 50,000 element-cases) once three cores may be used.
    std::string deck = kCaseList;
    for (int k = 0; k < 300; ++k)
      deck += "  - {name: C" + std::to_string(k) + ", factors: {dead: " +
              std::to_string(1 + 0.35 * (k % 8) / 7) + ", wind: " +
              std::to_string(1.5 * ((k % 7) - 3) / 3) + ", heat: " +
              std::to_string(0.6 * ((k % 5) - 2) / 2) + "}}\n";
    std::string text = frameDeck(deck);
    for (const char* count : {"elements: 3}", "elements: 4}", "elements: 2}"})
      for (std::size_t at = text.find(count); at != std::string::npos; at = text.find(count))
        text.replace(at, std::string(count).size(), "elements: 90}");
    const Study s = test::solveDeckText(text, "frame_many.yaml");
    const RunResult& run = *s.run;
    const Model& model = *run.model;
    const std::vector<CaseOutcome>& cases = casesOf(run.analyses.front());
    REQUIRE(cases.size() * model.elements().size() >= 100000);
    REQUIRE(setenv("BEAMROTOR_THREADS", "3", 1) == 0);
    const std::vector<AnalysisExtremes> split = runExtremes(run);
    const PreparedRun prepared = prepareRun(run);
    REQUIRE(unsetenv("BEAMROTOR_THREADS") == 0);
    // The reference: each case's extremes one after the other, as staticExtremes gives them.
    const bool chords = caseChordDeflections(model, cases.size());
    SolutionPolynomials summed;
    const std::vector<StaticExtremes>& got = split.front().cases;
    REQUIRE(got.size() == cases.size());
    for (std::size_t k = 0; k < cases.size(); ++k) {
      CAPTURE(cases[k].name);
      LoadedSolution solution = cases[k].on(model);
      if (cases[k].combination) {
        cases[k].polynomials->sumInto(summed);
        solution.polynomials = &summed;
      }
      const StaticExtremes one = staticExtremes(solution, PeaksKept::canGovern, chords);
      REQUIRE(got[k].peaks.size() == one.peaks.size());
      for (std::size_t e = 0; e < one.peaks.size(); ++e)
        for (BeamPeak ElementPeaks::*kind : {&ElementPeaks::stress, &ElementPeaks::shear, &ElementPeaks::moment}) {
          CHECK((got[k].peaks[e].*kind).element == (one.peaks[e].*kind).element);
          CHECK((got[k].peaks[e].*kind).s == (one.peaks[e].*kind).s);
          CHECK((got[k].peaks[e].*kind).value == (one.peaks[e].*kind).value);
        }
      REQUIRE(got[k].ranges.size() == one.ranges.size());
      for (std::size_t m = 0; m < one.ranges.size(); ++m)
        for (int c = 0; c < 6; ++c)
          for (MemberValue ComponentRange::*side : {&ComponentRange::max, &ComponentRange::min}) {
            CHECK((got[k].ranges[m][c].*side).element == (one.ranges[m][c].*side).element);
            CHECK((got[k].ranges[m][c].*side).s == (one.ranges[m][c].*side).s);
            CHECK((got[k].ranges[m][c].*side).value == (one.ranges[m][c].*side).value);
          }
      REQUIRE(got[k].chordDeflections.size() == one.chordDeflections.size());
      for (std::size_t m = 0; m < one.chordDeflections.size(); ++m)
        CHECK(got[k].chordDeflections[m].value == one.chordDeflections[m].value);
      CHECK(got[k].largestDisplacement.value == one.largestDisplacement.value);
      CHECK(got[k].largestDisplacement.element == one.largestDisplacement.element);
    }
    // The envelope of each member, computed whole by one part, against memberEnvelope alone.
    // Over the combinations that can govern, named by their index among all combinations.
    std::vector<LoadedSolution> combinations;
    std::vector<int> named;
    for (std::size_t k = 0, index = 0; k < cases.size(); ++k)
      if (cases[k].combination) {
        if (split.front().canGovern.at(k)) {
          combinations.push_back(cases[k].on(model));
          named.push_back(int(index));
        }
        ++index;
      }
    CHECK(combinations.size() < 300);
    const std::vector<std::vector<EnvelopeStation>>& stations =
        prepared.analyses.front().envelopeStations;
    REQUIRE(stations.size() == model.members().size());
    for (std::size_t m = 0; m < model.members().size(); ++m) {
      const std::vector<EnvelopeStation> one =
          memberEnvelope(combinations, model.members()[m].second, kIntervalsPerElement);
      REQUIRE(stations[m].size() == one.size());
      for (std::size_t i = 0; i < one.size(); ++i) {
        CHECK(stations[m][i].s == one[i].s);
        CHECK(stations[m][i].max == one[i].max);
        CHECK(stations[m][i].min == one[i].min);
        for (int f = 0; f < 6; ++f) {
          CHECK(stations[m][i].maxBy[f] == named.at(std::size_t(one[i].maxBy[f])));
          CHECK(stations[m][i].minBy[f] == named.at(std::size_t(one[i].minBy[f])));
        }
      }
    }
  }

  TEST_CASE("member ranges kept as values alone: the same values and the same envelope") {
    // What runExtremes keeps of many combinations of a large frame (RangesKept::values), against
    // the ranges with their places and against each member's ranges evaluated directly.
    const Study s = test::solveDeckText(frameDeck(kCases), "frame_values.yaml");
    const Model& model = *s.run->model;
    const std::vector<CaseOutcome>& cases = casesOf(s.run->analyses.front());
    REQUIRE(cases.size() == 6);
    SolutionPolynomials summed;
    std::vector<StaticExtremes> placed, values;
    for (const CaseOutcome& c : cases) {
      placed.push_back(caseExtremes(model, c, summed, false, RangesKept::withPlaces));
      values.push_back(caseExtremes(model, c, summed, false, RangesKept::values));
      CHECK(values.back().ranges.empty());
      REQUIRE(rangedMembers(values.back()) == model.members().size());
      REQUIRE(rangedMembers(placed.back()) == model.members().size());
    }
    for (std::size_t k = 0; k < cases.size(); ++k)
      for (std::size_t m = 0; m < model.members().size(); ++m) {
        // The direct evaluation: the case's own resultants (a combination's summed polynomials
        // give them to round-off: the bits are compared with the places kept, below).
        const auto direct = memberForceRanges(cases[k].on(model), model.members()[m].second);
        for (std::size_t f = 0; f < 6; ++f) {
          const RangeValues v = rangeValuesOf(values[k], m, f);
          CHECK(v.max == placed[k].ranges[m][f].max.value);
          CHECK(v.min == placed[k].ranges[m][f].min.value);
          // Round-off of a factored sum of three cases' resultants (about 1e6 N m at most).
          const double scale = 1 + std::abs(direct[f].max.value) + std::abs(direct[f].min.value);
          CHECK(std::abs(v.max - direct[f].max.value) <= 1e-9 * scale);
          CHECK(std::abs(v.min - direct[f].min.value) <= 1e-9 * scale);
        }
      }
    const std::vector<bool> canGovern = combinationsThatCanGovern(cases);
    const CaseEnvelope a = caseEnvelope(model, cases, placed, canGovern),
                       b = caseEnvelope(model, cases, values, canGovern);
    REQUIRE(a.members.size() == b.members.size());
    for (std::size_t m = 0; m < a.members.size(); ++m)
      for (std::size_t f = 0; f < 6; ++f) {
        CHECK(a.members[m][f].max.value == b.members[m][f].max.value);
        CHECK(a.members[m][f].max.by == b.members[m][f].max.by);
        CHECK(a.members[m][f].min.value == b.members[m][f].min.value);
        CHECK(a.members[m][f].min.by == b.members[m][f].min.by);
        CHECK(a.members[m][f].max.by >= 3);  // combinations only: cases 3, 4 and 5
      }
  }
  TEST_CASE("each combination's member ranges from the envelope's pass: the bits of its own") {
    // memberEnvelope ranges each combination's resultants on each element for the envelope;
    // the member ranges it gives from them are those staticExtremes computes combination by
    // combination (the same places, the same values, the first of equal ones kept), and its
    // stations are those of the envelope computed without them.
    const Study s = test::solveDeckText(frameDeck(kCases), "frame_merged.yaml");
    const Model& model = *s.run->model;
    const std::vector<CaseOutcome>& cases = casesOf(s.run->analyses.front());
    REQUIRE(cases.size() == 6);
    std::vector<LoadedSolution> combinations;
    std::vector<StaticExtremes> own;
    SolutionPolynomials summed;
    for (const CaseOutcome& c : cases)
      if (c.combination) {
        combinations.push_back(c.on(model));
        own.push_back(caseExtremes(model, c, summed, false, RangesKept::values));
      }
    REQUIRE(combinations.size() == 3);
    for (std::size_t m = 0; m < model.members().size(); ++m) {
      const std::vector<int>& elements = model.members()[m].second;
      std::vector<std::array<RangeValues, 6>> ranges;
      envelopeWithRanges(combinations, elements, ranges);
      REQUIRE(ranges.size() == combinations.size());
      for (std::size_t k = 0; k < combinations.size(); ++k)
        for (std::size_t f = 0; f < 6; ++f) {
          const RangeValues v = rangeValuesOf(own[k], m, f);
          CHECK(ranges[k][f].max == v.max);
          CHECK(ranges[k][f].min == v.min);
          CHECK(ranges[k][f].max >= ranges[k][f].min);
        }
    }
  }
  TEST_CASE("the envelope of many crossing and equal combinations: the bits of every one evaluated") {
    // The envelope skips candidates by bounds; the bits must be those of every combination
    // evaluated at its places (crossingDeck).
    const Study s = test::solveDeckText(crossingDeck(), "frame_crossing.yaml");
    const Model& model = *s.run->model;
    std::vector<LoadedSolution> combinations;
    for (const CaseOutcome& c : casesOf(s.run->analyses.front()))
      if (c.combination) combinations.push_back(c.on(model));
    REQUIRE(combinations.size() == 46);
    const std::size_t n = combinations.size();
    std::size_t stations = 0, ties = 0;
    for (const auto& [name, elements] : model.members()) {
      CAPTURE(name);
      std::vector<std::array<RangeValues, 6>> ranges;
      const std::vector<EnvelopeStation> env = envelopeWithRanges(combinations, elements, ranges);
      stations += env.size();
      for (std::size_t c = 0; c < 6; ++c) {
        const double roundOff = 1e-12 * resultantScale(combinations, elements, c);
        // 1. At each station: the largest and smallest of every combination evaluated there,
        //    to the bit, and the first combination giving each (the first of equal values).
        for (const EnvelopeStation& st : env) {
          int hiBy = 0, loBy = 0, equal = 0;
          double hi = valueAt(resultantOn(combinations[0], st.element, c), st.s), lo = hi;
          for (std::size_t k = 1; k < n; ++k) {
            const double v = valueAt(resultantOn(combinations[k], st.element, c), st.s);
            if (v == hi) ++equal;
            if (v > hi) hi = v, hiBy = int(k), equal = 0;
            if (v < lo) lo = v, loBy = int(k);
          }
          ties += equal > 0;
          CHECK(st.max[c] == hi);
          CHECK(st.maxBy[c] == hiBy);
          CHECK(st.min[c] == lo);
          CHECK(st.minBy[c] == loBy);
        }
        // 2. Between consecutive stations, one combination's polynomial.
        checkOnePolynomialBetween(env, combinations, c, roundOff);
      }
    }
    CHECK(stations >= 80);  // 83 when written
    CHECK(ties >= 200);     // exactly equal largest values at a station (307 when written)
  }

  TEST_CASE("the envelope over the combinations that can govern: every combination evaluated") {
    // What a run computes: the envelope along the members, its extremes, the reactions' and
    // the largest displacement's and stress's, over the combinations whose factors are corners
    // of all combinations' (CombinationHull.hpp). Against every combination evaluated: at each
    // station the largest (smallest) of all 46 equals the envelope's to round-off, the
    // combination named gives the envelope's value there to the bit and is a corner, and
    // between stations each side is one combination's polynomial, of all 46.
    const Study s = test::solveDeckText(crossingDeck(), "frame_corners.yaml");
    const RunResult& run = *s.run;
    const Model& model = *run.model;
    const std::vector<CaseOutcome>& cases = casesOf(run.analyses.front());
    const std::vector<AnalysisExtremes> extremes = runExtremes(run, MemberEnvelopes::computed);
    const AnalysisExtremes& x = extremes.front();
    // The factors' corners (dead, wind, heat): the grid's box [1, 1.35] x [-1.5, 1.5] x
    // [-1.2, 0.6] has 8 (combinations 0, 2, 12, 14, 15, 17, 27, 29); the second fan's
    // (1.35, 0, 1.2), combination 38, lies outside it and is a ninth. Every other combination
    // is inside the hull, on a face or edge of it, or repeats an earlier one.
    std::vector<std::size_t> corners;  // index among the combinations
    std::vector<LoadedSolution> all;
    for (std::size_t k = 0, index = 0; k < cases.size(); ++k) {
      if (!cases[k].combination) {
        CHECK_FALSE(x.canGovern.at(k));
        continue;
      }
      if (x.canGovern.at(k)) corners.push_back(index);
      all.push_back(cases[k].on(model));
      ++index;
    }
    CHECK(corners == std::vector<std::size_t>{0, 2, 12, 14, 15, 17, 27, 29, 38});
    const std::vector<bool> isCorner = [&] {
      std::vector<bool> out(all.size(), false);
      for (std::size_t k : corners) out[k] = true;
      return out;
    }();
    const CaseEnvelope envelope = caseEnvelope(model, cases, x.cases, x.canGovern);
    REQUIRE(x.memberEnvelopes.size() == model.members().size());
    for (std::size_t m = 0; m < model.members().size(); ++m) {
      const std::vector<int>& elements = model.members()[m].second;
      const std::vector<EnvelopeStation>& env = x.memberEnvelopes[m];
      CAPTURE(model.members()[m].first);
      for (std::size_t c = 0; c < 6; ++c) {
        const double roundOff = 1e-12 * resultantScale(all, elements, c);
        double largest = -1e300, smallest = 1e300;  // along the member, over all 46
        for (const EnvelopeStation& st : env) {
          double hi = -1e300, lo = 1e300;
          for (const LoadedSolution& k : all) {
            const double v = valueAt(resultantOn(k, st.element, c), st.s);
            hi = std::max(hi, v), lo = std::min(lo, v);
          }
          largest = std::max(largest, hi), smallest = std::min(smallest, lo);
          CHECK(std::abs(st.max[c] - hi) <= roundOff);
          CHECK(std::abs(st.min[c] - lo) <= roundOff);
          REQUIRE(isCorner.at(std::size_t(st.maxBy[c])));
          REQUIRE(isCorner.at(std::size_t(st.minBy[c])));
          CHECK(valueAt(resultantOn(all[std::size_t(st.maxBy[c])], st.element, c), st.s) == st.max[c]);
          CHECK(valueAt(resultantOn(all[std::size_t(st.minBy[c])], st.element, c), st.s) == st.min[c]);
        }
        checkOnePolynomialBetween(env, all, c, roundOff);
        // The member's extremes over the corners (envelope.members) against every
        // combination's own range along it (memberForceRanges).
        double hi = -1e300, lo = 1e300;
        for (const LoadedSolution& k : all) {
          const auto r = memberForceRanges(k, elements);
          hi = std::max(hi, r[c].max.value), lo = std::min(lo, r[c].min.value);
        }
        CHECK(std::abs(envelope.members.at(m)[c].max.value - hi) <= roundOff);
        CHECK(std::abs(envelope.members.at(m)[c].min.value - lo) <= roundOff);
        CHECK(std::abs(largest - hi) <= roundOff);
        CHECK(std::abs(smallest - lo) <= roundOff);
      }
    }
    // Reactions, the largest displacement and stress: the corners' largest are all's.
    for (std::size_t r = 0; r < envelope.reactions.size(); ++r) {
      double hi = -1e300, lo = 1e300, scale = 0;
      for (const CaseOutcome& c : cases)
        if (c.combination) {
          const double v = c.statics.reactions.at(r).value;
          hi = std::max(hi, v), lo = std::min(lo, v), scale = std::max(scale, std::abs(v));
        }
      CHECK(std::abs(envelope.reactions[r].second.max.value - hi) <= 1e-12 * scale);
      CHECK(std::abs(envelope.reactions[r].second.min.value - lo) <= 1e-12 * scale);
    }
    double displacement = 0;
    for (std::size_t k = 0; k < cases.size(); ++k)
      if (cases[k].combination)
        displacement = std::max(displacement, x.cases[k].largestDisplacement.value);
    CHECK(std::abs(envelope.largestDisplacement.value - displacement) <= 1e-12 * displacement);
  }
}

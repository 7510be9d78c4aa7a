// Exact extrema: the largest moment, stress and shear inside an element against the closed
// form of a propped beam with a support settlement and a distributed load (the peak lies
// between sample points), the same number in a check and in results.json, and a non-finite
// resultant making the quantity non-finite so that its check fails.
#include <doctest/doctest.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <sstream>

#include "fem/assembly/ElementExtrema.hpp"
#include "fem/assembly/Recovery.hpp"
#include "fem/model/StandardSections.hpp"
#include "problems/cli/Summary.hpp"
#include "problems/output/JsonWriter.hpp"
#include "problems/run/Measure.hpp"
#include "problems/run/Study.hpp"
#include "tests/Helpers.hpp"
#include "tests/problems/DeckTestSupport.hpp"

using namespace beamrotor;

namespace {

// Clamped at x = 0, propped at x = L and lifted there by d = -q L^4 / (48 E I), uniform load q
// (N/m along y, downward). The prop's force from w(L) = q L^4 / (8 E I) + R L^3 / (3 E I) = d
// (Gere & Goodno, table G-1, cases 1 and 4): R = 3 E I d / L^3 - 3 q L / 8 = -7 q L / 16.
// The moment of the part right of x, M(x) = R (L - x) + q (L - x)^2 / 2, is stationary where
// its shear vanishes, L - x = -R / q = 7 L / 16, with |M| = R^2 / (2 |q|) = 49 |q| L^2 / 512,
// larger than the root's |R L + q L^2 / 2| = |q| L^2 / 16. On 3 elements of 1 m it lies at
// s = 0.6875 of the middle element: between the 8 (and 4) sample points per element.
const std::string kProppedDeck = R"(
parameters: {L: 3, q: -2000, D: 0.06, E: 200e9, nu: 0.3}
derived:
  EI: E*pi*D^4/64
  lift: -q*L^4/(48*EI)
  R: 3*EI*lift/L^3 - 3*q*L/8
  M_peak: R^2 / (2*abs(q))
  x_peak: L + R/q
  sigma_peak: 32*M_peak/(pi*D^3)
  tau_peak: (3 + 2*nu)/(2*(1 + nu)) * abs(R + q*L) / (pi*D^2/4)
materials:
  - {name: steel, E: E, nu: nu, rho: 7850}
sections:
  - {name: rod, shape: circle, D: D}
segments:
  - {length: L, section: rod, elements: 3}
supports:
  - {name: wall, at: start, fix: clamped}
  - {name: prop, at: end, fix: [ux], prescribe: {uy: lift}}
loads:
  - {type: distributed, qy: q}
report: [x_peak]
checks:
  # Exact elements and exact extrema: round-off only.
  - {name: peak moment, quantity: moment max, reference: M_peak, tolerance: 1e-12}
  - {name: peak stress, quantity: stress max, reference: sigma_peak, tolerance: 1e-12}
  - {name: peak shear, quantity: shear max, reference: tau_peak, tolerance: 1e-12}
)";

Study solveProppedBeam() {
  return test::solveDeckText(kProppedDeck, "propped.yaml");
}

}  // namespace

TEST_SUITE("exact extrema") {
  TEST_CASE("propped beam with a settlement: the peak inside an element, exact everywhere") {
    const Study study = solveProppedBeam();
    REQUIRE(study.run);
    const RunResult& run = *study.run;
    const double L = 3, q = -2000, D = 0.06;
    const double mPeak = 49 * std::abs(q) * L * L / 512;
    const double sigmaPeak = 32 * mPeak / (test::kPi * D * D * D);
    REQUIRE(run.checks.size() == 3);
    for (const Check& c : run.checks) {
      CAPTURE(c.name);
      CHECK(c.pass());
    }
    // The deck's references are written independently of these numbers.
    CHECK(test::relError(run.checks[0].computed, mPeak) < 1e-12);
    CHECK(test::relError(run.checks[1].computed, sigmaPeak) < 1e-12);

    // results.json reports the very same number, at the stationary point.
    const StaticResult& r = *staticsOf(run.analyses.front());
    const Json doc = runJson(run);
    const Json& top = doc.at("analyses").at(0).at("max_stress");
    CHECK(top.at("value").get<double>() == run.checks[1].computed);
    CHECK(top.at("element").get<int>() == 1);
    // The stationary point is the zero of a linear shear: round-off in its place.
    CHECK(std::abs(top.at("x").get<double>() - 9 * L / 16) < 1e-12 * L);

    // What sampling saw (before: 8 stations per element for checks, 4 for results.json): the
    // nearest stations lie h/16 = L/48 from the peak (x = 1.625 and 1.75 against 1.6875), where
    // M = M_peak - |q| (L/48)^2 / 2, i.e. 2.3e-3 relative below it. The exact peak must be above
    // every sample.
    for (int perElement : {4, 8}) {
      double sampled = 0;
      for (const BeamStation& st : recoverBeamFields({*run.model, r.displacement}, perElement))
        sampled = std::max(sampled, std::hypot(st.forces.My, st.forces.Mz));
      const double deficit = std::abs(q) * (L / 48) * (L / 48) / 2 / mPeak;
      CHECK(test::relError(sampled, mPeak) == doctest::Approx(deficit).epsilon(1e-9));
      CHECK(sampled < run.checks[0].computed);
    }
  }

  TEST_CASE("a non-finite resultant makes the largest value NaN and its check fail") {
    const Study study = solveProppedBeam();
    REQUIRE(study.run);
    RunResult run = *study.run;
    // A NaN in the nodal solution (as an ill-conditioned solve could leave) reaches the
    // resultants of the two elements at that node only; std::max would drop it and report
    // the others' largest value.
    StaticResult& r = *staticsOf(run.analyses.front());
    r.displacement(1, int(Dof::rz)) = std::numeric_limits<double>::quiet_NaN();
    for (const char* text : {"moment max", "stress max", "shear max"}) {
      CAPTURE(text);
      const double value = measure(parseQuantity(text), run.analyses.front(), *run.model);
      CHECK(std::isnan(value));
      Check c{"peak", value, 1.0, 0.5, text, std::nullopt, ""};
      CHECK_FALSE(c.pass());
      run.checks = {c};
      std::ostringstream table;
      CHECK(cli::printChecks(table, study.deck, {&run}, {}) == 1);
      CHECK(table.str().find(std::string("FAIL  peak")) != std::string::npos);
      CHECK(table.str().find(text) != std::string::npos);
    }
    // The element peaks themselves.
    SectionForceSeries nan;
    nan.c[1].Mz = std::numeric_limits<double>::quiet_NaN();
    const auto& line = *asLine(run.model->elements().front());
    const ElementPeaks p = elementPeaks(line, nan);
    CHECK(std::isnan(p.moment.value));
    CHECK(std::isnan(p.stress.value));
    CHECK(std::isnan(largestPeak({ElementPeaks{}, p}, &ElementPeaks::moment)->value));
  }

  TEST_CASE("the largest stress over rounded corners and angles: exact against dense sampling") {
    // Resultants quadratic in s with the peak inside the element; the fibres include arcs (the
    // hollow rectangle's rounded corners, the angle's toes, the tube). Sampling at 2e5 points
    // misses the peak by at most f'' h^2 / 8, about 1e-11 of it: the exact peak must lie at
    // or above every sample and within 1e-9 of the best.
    const Material steel = Material::fromEnu("steel", 210e9, 0.3, 7850);
    SectionForceSeries forces;
    // N = 2e4 - 1e4 s, My = 6e3 s (1.3 - s), Mz = -1e4 s (1 - s): small at the ends.
    forces.c[0] = {2e4, 0, 0, 0, 0, 0};
    forces.c[1] = {-1e4, 0, 0, 0, 7.8e3, -1e4};
    forces.c[2] = {0, 0, 0, 0, -6e3, 1e4};
    for (const Section& section :
         {hollowRectangleSection("rhs", steel, 0.2, 0.1, 0.008, 0.03, 0.02),
          angleSection("angle", steel, 0.15, 0.09, 0.01, 0.012, 0.006),
          Section::tube("tube", steel, 0.1, 0.006)}) {
      CAPTURE(section.name);
      Model model;
      test::uniformBeam(model, 1.0, std::make_shared<Section>(section), 1, DofSet::frame3d());
      const ElementPeaks p = elementPeaks(*asLine(model.elements().front()), forces);
      double sampled = 0;
      for (int k = 0; k <= 200000; ++k)
        sampled = std::max(sampled, maxNormalStress(section, forces.at(k / 200000.0)));
      CHECK(p.stress.value >= sampled * (1 - 1e-14));
      CHECK(p.stress.value <= sampled * (1 + 1e-9));
      CHECK(p.stress.s > 0);
      CHECK(p.stress.s < 1);
    }
  }

  TEST_CASE("the moment's peak in 3d from the closed forms and the bracketed Newton steps") {
    // My and Mz quadratic with their peaks apart (uniform loads in both planes and different
    // end moments): |M|^2 is quartic, its derivative a cubic whose bracket comes from the
    // closed-form zeros of its derivative. Reference: a dense sampling refined about its best
    // sample twice, 2e4 places each over a window 4e-4 and then 4e-8 wide: the last spacing
    // is 2e-12, below which the peak's curvature changes |M| by 1e-23 of it (round-off).
    const Material steel = Material::fromEnu("steel", 210e9, 0.3, 7850);
    const Section section = Section::tube("tube", steel, 0.1, 0.006);
    Model model;
    test::uniformBeam(model, 1.0, std::make_shared<Section>(section), 1, DofSet::frame3d());
    const LineElement& line = *asLine(model.elements().front());
    SectionForceSeries forces;
    // My = -3e3 + 1.7e4 s - 1.2e4 s^2 (peak at s = 0.708), Mz = 2e3 + 9e3 s - 1.1e4 s^2
    // (peak at s = 0.409).
    forces.c[0] = {0, 0, 0, 0, -3e3, 2e3};
    forces.c[1] = {0, 0, 0, 0, 1.7e4, 9e3};
    forces.c[2] = {0, 0, 0, 0, -1.2e4, -1.1e4};
    const auto moment = [&](double s) {
      const SectionForces f = forces.at(s);
      return std::hypot(f.My, f.Mz);
    };
    double best = 0, bestAt = 0;
    double from = 0, width = 1;
    for (int round = 0; round < 3; ++round) {
      for (int k = 0; k <= 20000; ++k) {
        const double s = std::clamp(from + width * k / 20000.0, 0.0, 1.0);
        if (moment(s) > best) best = moment(s), bestAt = s;
      }
      width = round == 0 ? 4e-4 : 4e-8;
      from = bestAt - width / 2;
    }
    const ElementPeaks p = elementPeaks(line, forces);
    CHECK(p.moment.s > 0.4);
    CHECK(p.moment.s < 0.71);
    // Both sides carry round-off of a few ulps of |M| (hypot, Horner; an ulp of 4530 is 2e-16
    // of it): measured 2 ulps apart.
    CHECK(std::abs(p.moment.value - best) <= 1e-15 * best);
    // A flat peak fixes its place only to about the square root of round-off.
    CHECK(std::abs(p.moment.s - bestAt) < 1e-7);
  }

  TEST_CASE("zeros in closed form and by bracketed Newton steps, to the last bits") {
    // Quadratic 1e-3 (s - 0.2)(s - 0.9) and cubic (s - 0.1)(s - 0.45)(s - 0.8): each zero to
    // round-off, where bisection would also reach it but in about 53 halvings. The cubic's
    // Newton steps stop once the value is within its Horner round-off bound, 8 eps sum |c_k|
    // s^k: over the slope at each zero (0.245, 0.1225, 0.245) at most 7e-16, 8.9e-15 and
    // 1.3e-14 in its place.
    const auto nearest = [](const std::vector<double>& zeros, double x) {
      double d = 1;
      for (double z : zeros) d = std::min(d, std::abs(z - x));
      return d;
    };
    const std::vector<double> z2 = zerosInUnitInterval({1.8e-4, -1.1e-3, 1e-3});
    for (double x : {0.2, 0.9}) CHECK(nearest(z2, x) <= 4e-16);
    CHECK(nearest(z2, 0.55) <= 4e-16);  // the vertex, the derivative's zero
    const std::vector<double> z3 = zerosInUnitInterval({-0.036, 0.485, -1.35, 1});
    for (double x : {0.1, 0.45, 0.8}) CHECK(nearest(z3, x) <= 1.5e-14);
  }

  TEST_CASE("zeros in [0, 1]: simple and double zeros, to round-off") {
    // (s - 0.3)^2 (s - 0.7) = s^3 - 1.3 s^2 + 0.51 s - 0.063: a double zero (no sign change) and
    // a simple one; (s - 2)(s + 1) has none inside (0.5, its derivative's zero, may be listed).
    const auto near = [](const std::vector<double>& zeros, double x) {
      for (double z : zeros)
        if (std::abs(z - x) < 1e-12) return true;
      return false;
    };
    const std::vector<double> z = zerosInUnitInterval({-0.063, 0.51, -1.3, 1});
    CHECK(near(z, 0.3));
    CHECK(near(z, 0.7));
    for (double s : zerosInUnitInterval({-2, -1, 1})) CHECK(s == doctest::Approx(0.5));
    // Degree 6 with leading coefficients of very different size: (s - 0.25)(s - 0.5)(s - 0.75)
    // times 1e20 (s^3 + 1), whose other zeros lie outside.
    std::vector<double> p{0, 0, 0, 0, 0, 0, 0};
    const std::vector<double> a{-0.09375, 0.6875, -1.5, 1}, b{1e20, 0, 0, 1e20};
    for (std::size_t i = 0; i < a.size(); ++i)
      for (std::size_t j = 0; j < b.size(); ++j) p[i + j] += a[i] * b[j];
    const std::vector<double> z6 = zerosInUnitInterval(p);
    for (double x : {0.25, 0.5, 0.75}) CHECK(near(z6, x));
  }
}

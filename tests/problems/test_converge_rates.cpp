// The convergence study measures the rates the theory predicts on closed-form cases:
// Euler-Bernoulli frequencies converge as h^4 with the consistent mass and h^2 with the
// lumped mass; end-loaded static beams are exact at the nodes (Euler-Bernoulli and the
// locking-free Timoshenko element); a uniformly loaded beam sampled between nodes converges
// as h^4 with an error constant derived below.
#include <doctest/doctest.h>

#include <cmath>
#include <string>

#include "fem/assembly/Recovery.hpp"
#include "fem/static/Static.hpp"
#include "problems/converge/ConvergeStudy.hpp"
#include "problems/converge/ConvergenceRates.hpp"
#include "problems/deck/DeckReader.hpp"
#include "tests/Helpers.hpp"

namespace beamrotor {

namespace {

/// A steel cantilever (L = 1 m, D = 0.02 m: L/D = 50) clamped at the root with a tip force,
/// 2 elements on level 0; `checks` is the deck's checks block.
Deck cantilever(const std::string& formulation, const std::string& checks) {
  const std::string text = R"(
parameters: {L: 1.0, D: 0.02, P: 100, E: 210e9, nu: 0.3, rho: 7850}
derived:
  I: pi * D^4 / 64
  A: pi * D^2 / 4
  G: E / (2 * (1 + nu))
  kappa: 6 * (1 + nu) / (7 + 6 * nu)
model: {dimension: planar, formulation: )" +
                           formulation + R"(}
materials: [{name: steel, E: E, nu: nu, rho: rho}]
sections: [{name: rod, shape: circle, D: D}]
segments: [{length: L, section: rod, elements: 2}]
points: [{name: tip, at: L}]
supports: [{name: root, at: start, fix: clamped}]
loads: [{type: point, at: tip, fy: -P}]
analyses: [{type: static}, {type: modal, modes: 2}]
checks:
)" + checks;
  return readDeck(parseDeckText(text, "cantilever_rates.yaml"), {});
}

/// First cantilever root of cos(x) cosh(x) = -1 to 15 digits (Blevins, Formulas for Natural
/// Frequency and Mode Shape, table 8-1), so the reference adds no error above round-off.
const std::string kFrequency1 =
    "  - {name: f1, quantity: frequency 1, tolerance: 1,"
    " reference: 1.87510406871196^2 / (2*pi*L^2) * sqrt(E*I/(rho*A))}\n";

const ConvergeSeries& seriesOf(const ConvergeStudy& s, const std::string& method) {
  for (const ConvergeSeries& series : s.series)
    if (series.method.name == method) return series;
  FAIL("no series " << method);
  return s.series.front();
}

ConvergeOptions levels(int n, const std::string& quantity = "") {
  ConvergeOptions o;
  o.levels = n;
  o.repeats = 1;
  o.quantity = quantity;
  return o;
}

}  // namespace

TEST_SUITE("converge rates") {
  TEST_CASE("Euler-Bernoulli frequency: order 4 with the consistent mass, 2 with the lumped") {
    // 2, 4, 8, 16, 32 elements: the consistent-mass error falls from ~1e-4 to ~1e-9, still far
    // above round-off (~1e-13 for these small systems), so every measured order is asymptotic.
    const ConvergeStudy s = runConvergence(cantilever("euler-bernoulli", kFrequency1), levels(5));
    const ConvergeSeries& consistent = seriesOf(s, "eb-consistent");
    const ConvergeSeries& lumped = seriesOf(s, "eb-lumped");
    CHECK_FALSE(consistent.extrapolated);
    for (int k = 2; k < 5; ++k) {
      INFO("level " << k);
      REQUIRE(consistent.levels[k].order);
      REQUIRE(lumped.levels[k].order);
      CHECK(std::abs(*consistent.levels[k].order - 4) < 0.3);
      CHECK(std::abs(*lumped.levels[k].order - 2) < 0.3);
    }
    // The Timoshenko elements converge to the Timoshenko beam's frequency, below the
    // Euler-Bernoulli one by the shear and rotary-inertia correction, of order (D/L)^2.
    const ConvergeSeries& timoshenko = seriesOf(s, "timoshenko");
    CHECK(timoshenko.levels.back().value < consistent.levels.back().value);
    CHECK(timoshenko.levels.back().error < 1e-3);
  }

  TEST_CASE("end-loaded cantilever: nodal values exact for Euler-Bernoulli and Timoshenko") {
    // Named with --quantity: by default converge would pass over a quantity exact on every
    // mesh (test_converge_decks.cpp). The tip deflection of Euler-Bernoulli, P L^3/(3 E I), and of
    // Timoshenko, plus the shear term P L/(kappa G A) (kappa of a circle, Cowper 1966). Both
    // elements reproduce the exact solution at the nodes (their shape functions contain it), so
    // every level is exact to round-off: cond(K) of these <= 32-element cantilevers is below ~1e8,
    // so 1e-10 bounds cond * eps with a margin (observed ~1e-15).
    constexpr double kRoundOff = 1e-10;
    const ConvergeStudy eb =
        runConvergence(cantilever("euler-bernoulli",
                                  "  - {name: tip, quantity: displacement tip uy, tolerance: 1,"
                                  " reference: -P*L^3/(3*E*I)}\n"),
                       levels(5, "displacement tip uy"));
    for (const ConvergeLevel& l : seriesOf(eb, "eb-consistent").levels) CHECK(l.error < kRoundOff);
    CHECK(eb.series.size() == 4);  // statics: no lumped-mass series

    const ConvergeStudy tim =
        runConvergence(cantilever("timoshenko",
                                  "  - {name: tip, quantity: displacement tip uy, tolerance: 1,"
                                  " reference: -P*L^3/(3*E*I) - P*L/(kappa*G*A)}\n"),
                       levels(5, "displacement tip uy"));
    for (const ConvergeLevel& l : seriesOf(tim, "timoshenko").levels) CHECK(l.error < kRoundOff);
    // The locking linear element is far off on 2 elements at L/D = 50 (stiffer: smaller
    // deflection) and improves with every level, still pre-asymptotic at 32 elements.
    const ConvergeSeries& naive = seriesOf(tim, "timoshenko-linear-full");
    CHECK(naive.levels.front().error > 0.5);
    for (std::size_t k = 1; k < naive.levels.size(); ++k)
      CHECK(naive.levels[k].error < naive.levels[k - 1].error);
  }

  TEST_CASE(
      "uniform load, sampled between nodes: exact with the span load, q h^4 / (384 E I) without") {
    // Euler-Bernoulli elements with consistent loads give exact nodal values (their shape
    // functions contain the Green's function of the beam). Between nodes the cubic Hermite
    // interpolant of the exact quartic w misses w''''(xi)/4! (x - a)^2 (x - b)^2 (e.g. Burden &
    // Faires, Numerical Analysis, thm 3.9); with w'''' = q/(E I) constant that is
    // q/(24 E I) (h/2)^4 = q h^4 / (384 E I) at the element middle, which is exactly the
    // clamped-clamped span solution the element adds when its load is applied. At midspan of
    // a simply supported span (w = 5 q L^4 / (384 E I)) on an odd number N of elements the
    // interpolant alone is off by exactly (h/L)^4 / 5 = 1/(5 N^4) (order 4, inside), and the
    // field with the span load is exact.
    const double L = 2.0, q = -5000;
    const auto section = test::steelRectangle(0.04, 0.06);
    const double EI = section->EIz();
    const double exact = 5 * q * std::pow(L, 4) / (384 * EI);
    for (int N : {1, 3, 5, 7, 9, 15}) {
      Model model;
      const Line line = test::uniformBeam(model, L, section, N);
      for (Beam* b : line.beams) b->setDistributedLoad({0, q, 0});
      model.addSupport({"left", line.nodes.front(), {{Dof::ux, 0}, {Dof::uy, 0}}});
      model.addSupport({"right", line.nodes.back(), {{Dof::uy, 0}}});
      const StaticResult r = solveStatic(model);
      const Beam& middle = *line.beams[N / 2];
      const auto nodal = displacementAlong(middle, r.displacement, 0.5, SpanLoad::none);
      const auto field = displacementAlong(middle, r.displacement, 0.5, SpanLoad::applied);
      const int uy = int(Dof::uy), rz = int(Dof::rz);
      INFO("N = " << N);
      // The error is exactly 1 / (5 N^4) up to round-off in the nodal values, measured up to
      // 1.8e-13 relative (N = 15), i.e. 5 N^4 times that relative to the error: 4.5e-8 at
      // N = 15, 5.7e-10 at N = 9. Asked: 1e-7.
      CHECK(test::relError(test::relError(nodal[uy], exact), 1 / (5 * std::pow(N, 4))) < 1e-7);
      CHECK(std::abs(nodal[uy]) < std::abs(exact));
      // Round-off of the solve (cond(K) ~ 1e5 at 15 elements times eps; 1.8e-13 measured).
      CHECK(test::relError(field[uy], exact) < 1e-12);
      // The slope at midspan vanishes by symmetry (end slopes q L^3 / (24 E I)).
      CHECK(std::abs(field[rz]) < 1e-12 * std::abs(q * L * L * L / (24 * EI)));
    }
  }

  TEST_CASE("Richardson extrapolation recovers the limit and the order") {
    // q(h) = 3 - 0.7 h^2 exactly: three levels give the limit 3 and p = 2 to round-off.
    const auto q = [](double h) { return 3 - 0.7 * h * h; };
    const Extrapolation e = richardson(q(0.4), q(0.2), q(0.1));
    REQUIRE(e.order);
    CHECK(*e.order == doctest::Approx(2).epsilon(1e-12));
    CHECK(e.value == doctest::Approx(3).epsilon(1e-14));
    // No asymptotic range (differences of opposite sign): the finest value, no order.
    CHECK_FALSE(richardson(1, 2, 1.5).order);
    CHECK(observedOrder(1e-4, 1e-4 / 16).value() == doctest::Approx(4).epsilon(1e-12));
    CHECK_FALSE(observedOrder(1e-4, 0));
  }

  TEST_CASE("without a closed form the reference is extrapolated and agrees with it") {
    // The same cantilever frequency with no check: each method's limit is its own Richardson
    // estimate from 8, 16, 32 elements. For the consistent mass (order 4, error ~4e-9 on 32
    // elements) the extrapolated limit must match the closed form far better than the finest
    // mesh does: to 1e-10, against 1.4e-8 for the 8-element error / 16^2 remaining terms.
    Deck deck = cantilever("euler-bernoulli", "  []\n");
    ConvergeOptions o = levels(5);
    o.quantity = "frequency 1";
    const ConvergeStudy s = runConvergence(deck, o);
    const ConvergeSeries& consistent = seriesOf(s, "eb-consistent");
    CHECK(consistent.extrapolated);
    CHECK(s.check.empty());
    REQUIRE(consistent.extrapolationOrder);
    CHECK(std::abs(*consistent.extrapolationOrder - 4) < 0.3);
    const Deck withCheck = cantilever("euler-bernoulli", kFrequency1);
    const double exact = withCheck.checks.front().reference;
    CHECK(test::relError(consistent.reference, exact) < 1e-10);
    CHECK(test::relError(consistent.reference, exact) <
          test::relError(consistent.levels.back().value, exact));
  }

  TEST_CASE("a deck with accuracy: the study keeps its own meshes (deck mesh times 2^k)") {
    Deck deck = cantilever("euler-bernoulli", kFrequency1);
    deck.accuracy = DeckAccuracy{1e-3, {}};
    const ConvergeStudy s = runConvergence(deck, levels(3));
    const ConvergeSeries& consistent = seriesOf(s, "eb-consistent");
    CHECK(consistent.levels[0].elements == 2);
    CHECK(consistent.levels[2].elements == 8);
  }

  TEST_CASE("a quantity the deck cannot give or too few levels is a DeckError") {
    const Deck deck = cantilever("euler-bernoulli", kFrequency1);
    ConvergeOptions o = levels(1);
    CHECK_THROWS_WITH_AS(runConvergence(deck, o), doctest::Contains("--levels: must be from 2"),
                         DeckError);
    o = levels(3);
    o.quantity = "frequency x";
    CHECK_THROWS_AS(runConvergence(deck, o), DeckError);
    o.quantity = "displacement nowhere uy";
    CHECK_THROWS_WITH_AS(runConvergence(deck, o), doctest::Contains("--quantity"), DeckError);
    o.quantity = "history x max";
    CHECK_THROWS_WITH_AS(runConvergence(deck, o), doctest::Contains("no analysis"), DeckError);
  }
}

}  // namespace beamrotor

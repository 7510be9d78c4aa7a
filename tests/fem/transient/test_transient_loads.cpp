// Loads as functions of time: each kind against values worked out by hand.
#include <doctest/doctest.h>

#include <cmath>
#include <numbers>

#include "fem/transient/TimeLoad.hpp"
#include "tests/Helpers.hpp"

using namespace beamrotor;
using beamrotor::test::kPi;

namespace {
// The functions are evaluated formulas: they agree with hand values to round-off.
constexpr double kLoadsRoundOff = 1e-14;
}  // namespace

TEST_SUITE("transient loads") {
  TEST_CASE("piecewise: zero before the first piece, each piece sees absolute time") {
    const TimeFunction f =
        timefn::piecewise({{0.0, timefn::constant(1)}, {2.0, [](double t) { return t * t; }}});
    CHECK(f(-1) == 0);
    CHECK(f(0) == 1);
    CHECK(f(1.999) == 1);
    CHECK(f(2) == 4);
    CHECK(f(3) == 9);
    CHECK_THROWS_AS(timefn::piecewise({{1.0, timefn::constant(0)}, {1.0, timefn::constant(1)}}),
                    std::invalid_argument);
    CHECK_THROWS_AS(timefn::piecewise({}), std::invalid_argument);
  }

  TEST_CASE("harmonic series: mean + sum A_k cos(k w t + phi_k)") {
    const double w = 3;
    const TimeFunction f = timefn::harmonicSeries(w, {{1, 2.0, 0.0}, {3, 0.5, kPi / 2}}, 1.0);
    for (double t : {0.0, 0.1, 0.7, 2.3}) {
      const double expected = 1 + 2 * std::cos(w * t) - 0.5 * std::sin(3 * w * t);
      CHECK(f(t) == doctest::Approx(expected).epsilon(kLoadsRoundOff));
    }
  }

  TEST_CASE("tabulated: linear between points, end values held outside") {
    const TimeFunction f = timefn::tabulated({0, 1, 3}, {0, 10, -10});
    CHECK(f(-5) == 0);
    CHECK(f(0.25) == doctest::Approx(2.5).epsilon(kLoadsRoundOff));
    CHECK(f(1) == 10);
    CHECK(f(2) == doctest::Approx(0).epsilon(kLoadsRoundOff));
    CHECK(f(2.5) == doctest::Approx(-5).epsilon(kLoadsRoundOff));
    CHECK(f(7) == -10);
    CHECK_THROWS_AS(timefn::tabulated({0, 0}, {1, 2}), std::invalid_argument);
    CHECK_THROWS_AS(timefn::tabulated({0, 1}, {1}), std::invalid_argument);
  }

  TEST_CASE("periodic: repeats [0, period) before and after the start") {
    const TimeFunction saw = timefn::periodic([](double tau) { return tau; }, 2.0, 0.5);
    CHECK(saw(0.5) == 0);
    CHECK(saw(1.5) == doctest::Approx(1).epsilon(kLoadsRoundOff));
    CHECK(saw(2.6) == doctest::Approx(0.1).epsilon(1e-13));
    CHECK(saw(0.0) == doctest::Approx(1.5).epsilon(kLoadsRoundOff));  // before the start: repeated
    for (double t = 0; t < 20; t += 0.37) CHECK(saw(t) >= 0);
    for (double t = 0; t < 20; t += 0.37) CHECK(saw(t) < 2);
    CHECK_THROWS_AS(timefn::periodic(timefn::constant(0), 0), std::invalid_argument);
  }

  TEST_CASE("a point load at a named point") {
    Model m;
    m.nameNode("tip", m.addNode({1, 0, 0}));
    const TimeLoad l = pointTimeLoad(m, "tip", Dof::uy, -5, timefn::sine(1, 2));
    REQUIRE(l.pattern.size() == 1);
    CHECK(l.pattern[0].node == 0);
    CHECK(l.pattern[0].value == -5);
    CHECK(l.factor(kPi / 4) == doctest::Approx(1).epsilon(kLoadsRoundOff));
    CHECK_THROWS_AS(pointTimeLoad(m, "nowhere", Dof::uy, 1, timefn::constant(1)),
                    std::out_of_range);
  }
}

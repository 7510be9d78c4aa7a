// Cantilever statics against the closed forms of beam theory.
#include <doctest/doctest.h>

#include "fem/static/Static.hpp"
#include "tests/Helpers.hpp"

using namespace beamrotor;
using namespace beamrotor::test;

// Hermite cubics reproduce the exact deflection of an end-loaded beam: only round-off remains
// (condition number ~1e6 for these models times machine epsilon ~1e-16).
constexpr double kExact = 1e-10;

TEST_SUITE("statics") {
  TEST_CASE("Euler-Bernoulli cantilever: tip force and tip moment are exact") {
    const double L = 2.0, P = 1500.0, M0 = 800.0;
    const auto sec = steelCircle(0.05);
    const double EI = sec->EIz();
    for (int n : {1, 7}) {
      CAPTURE(n);
      SUBCASE("tip force") {
        Model m;
        const Line line = uniformBeam(m, L, sec, n);
        clamp(m, "root", line.nodes.front(), DofSet::planar());
        m.addLoad({line.nodes.back(), Dof::uy, -P});
        const StaticResult r = solveStatic(m);
        CHECK(relError(r.displacement(line.nodes.back(), 1), -P * L * L * L / (3 * EI)) < kExact);
        CHECK(relError(r.displacement(line.nodes.back(), 5), -P * L * L / (2 * EI)) < kExact);
        CHECK(relError(r.reaction("root", Dof::uy), P) < kExact);
        CHECK(relError(r.reaction("root", Dof::rz), P * L) < kExact);
      }
      SUBCASE("tip moment") {
        Model m;
        const Line line = uniformBeam(m, L, sec, n);
        clamp(m, "root", line.nodes.front(), DofSet::planar());
        m.addLoad({line.nodes.back(), Dof::rz, M0});
        const StaticResult r = solveStatic(m);
        CHECK(relError(r.displacement(line.nodes.back(), 1), M0 * L * L / (2 * EI)) < kExact);
        CHECK(relError(r.displacement(line.nodes.back(), 5), M0 * L / EI) < kExact);
      }
    }
  }
}

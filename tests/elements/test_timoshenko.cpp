// Timoshenko elements: the interdependent-interpolation element is exact for an end-loaded
// cantilever at every slenderness; the naive linear element with full integration locks.
#include <doctest/doctest.h>

#include "fem/static/Static.hpp"
#include "tests/Helpers.hpp"

using namespace beamrotor;
using namespace beamrotor::test;

namespace {

/// Tip deflection of a cantilever of length L, square section h x h, tip force P.
double tipDeflection(double L, double h, int n, BeamTheory theory) {
  Model m;
  const Line line = uniformBeam(m, L, steelRectangle(h, h), n, DofSet::planar(), {theory});
  clamp(m, "root", line.nodes.front(), DofSet::planar());
  m.addLoad({line.nodes.back(), Dof::uy, -1000.0});
  return -solveStatic(m).displacement(line.nodes.back(), 1);
}

double exactTimoshenko(double L, double h) {
  const auto s = steelRectangle(h, h);
  const double P = 1000.0;
  return P * L * L * L / (3 * s->EIz()) + P * L / (s->kappaY * s->material.G * s->A);
}

}  // namespace

TEST_SUITE("timoshenko") {
  TEST_CASE("interdependent interpolation is exact for a tip-loaded cantilever") {
    // Exact element: round-off only. The tolerance grows with slenderness because the
    // condition number of K grows like (L/h)^2.
    for (double slenderness : {2.0, 10.0, 100.0, 1000.0})
      for (int n : {1, 4, 13}) {
        CAPTURE(slenderness);
        CAPTURE(n);
        const double L = 1.0, h = L / slenderness;
        CHECK(relError(tipDeflection(L, h, n, BeamTheory::timoshenko), exactTimoshenko(L, h)) <
              1e-9);
      }
  }

  TEST_CASE("linear element with full integration locks as L/h grows; reduced does not") {
    const double L = 1.0;
    double previous = 0;
    for (double slenderness : {10.0, 100.0, 1000.0, 10000.0}) {
      CAPTURE(slenderness);
      const double h = L / slenderness, exact = exactTimoshenko(L, h);
      const double locked =
          relError(tipDeflection(L, h, 4, BeamTheory::timoshenkoLinearFullIntegration), exact);
      const double reduced =
          relError(tipDeflection(L, h, 4, BeamTheory::timoshenkoLinearReducedIntegration), exact);
      MESSAGE("L/h = " << slenderness << ": full integration error " << locked
                       << ", reduced integration error " << reduced);
      CHECK(locked > previous);  // locking worsens monotonically with slenderness
      previous = locked;
      // Reduced integration: the one-point element under-predicts a slender cantilever's tip
      // deflection by 1/(4 n^2) = 1.5625 % at n = 4 whatever L/h (no locking); shear adds a
      // part the element gets exactly, so the error departs from that by O((h/L)^2) only.
      CHECK(std::abs(reduced - 1.0 / (4 * 4 * 4)) < 2e-4);
    }
    const double h = L / 1000;
    CHECK(relError(tipDeflection(L, h, 4, BeamTheory::timoshenkoLinearFullIntegration),
                   exactTimoshenko(L, h)) > 0.5);
  }
}

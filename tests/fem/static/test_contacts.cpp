// Contact constraints: gaps and unilateral supports against closed forms, and structures
// that stand only on their stops.
#include <doctest/doctest.h>

#include "fem/solvers/Errors.hpp"
#include "fem/static/Static.hpp"
#include "tests/Helpers.hpp"

using namespace beamrotor;
using namespace beamrotor::test;

namespace {
constexpr double kContactsExact = 1e-10;  // exact elements, exact elimination: round-off only
constexpr double kInf = std::numeric_limits<double>::infinity();
}  // namespace

TEST_SUITE("contacts") {
  TEST_CASE("cantilever tip over a gap: open below the closing load, on the stop above") {
    const double L = 1.2, gap = 0.002;
    const auto s = steelCircle(0.04);
    const double k = 3 * s->EIz() / (L * L * L), closing = k * gap;
    for (double P : {0.5 * closing, 0.999 * closing, closing, 1.5 * closing, 4 * closing}) {
      CAPTURE(P);
      Model m;
      const Line line = uniformBeam(m, L, s, 6);
      clamp(m, "root", line.nodes.front(), DofSet::planar());
      m.addContact({"floor", line.nodes.back(), Dof::uy, -gap, kInf});
      m.addLoad({line.nodes.back(), Dof::uy, -P});
      const StaticResult r = solveStatic(m);
      const ContactState& c = r.contacts.at(0);
      const double tip = r.displacement(line.nodes.back(), 1);
      if (P <= closing) {
        CHECK_FALSE(c.active);
        CHECK(relError(tip, -P / k) < kContactsExact);
        CHECK(std::abs(c.gap - (gap - P / k)) < kContactsExact * gap);
      } else {
        CHECK(c.active);
        CHECK(relError(tip, -gap) < kContactsExact);
        CHECK(relError(c.force, P - closing) < kContactsExact);  // the floor pushes up
      }
    }
  }

  TEST_CASE("a beam resting on two unilateral supports") {
    const double L = 2.0;
    SUBCASE("pushed down it stands on both, like a simply supported beam") {
      Model m;
      const auto s = steelCircle(0.05);
      const Line line = uniformBeam(m, L, s, 4);
      m.addSupport({"axial", line.nodes.front(), {{Dof::ux, 0}}});
      m.addContact({"a", line.nodes.front(), Dof::uy, 0, kInf});
      m.addContact({"b", line.nodes.back(), Dof::uy, 0, kInf});
      m.addLoad({line.nodes[2], Dof::uy, -1000});
      const StaticResult r = solveStatic(m);
      CHECK(r.contacts[0].active);
      CHECK(r.contacts[1].active);
      CHECK(relError(r.contacts[0].force, 500) < kContactsExact);
      CHECK(relError(r.displacement(line.nodes[2], 1), -1000 * L * L * L / (48 * s->EIz())) <
            kContactsExact);
    }
    SUBCASE("pulled up it lifts off: the error names the free dofs") {
      Model m;
      const Line line = uniformBeam(m, L, steelCircle(0.05), 4);
      m.addSupport({"axial", line.nodes.front(), {{Dof::ux, 0}}});
      m.addContact({"a", line.nodes.front(), Dof::uy, 0, kInf});
      m.addContact({"b", line.nodes.back(), Dof::uy, 0, kInf});
      m.addLoad({line.nodes[2], Dof::uy, +1000});
      CHECK_THROWS_AS(solveStatic(m), UnsupportedStructure);
    }
  }
}

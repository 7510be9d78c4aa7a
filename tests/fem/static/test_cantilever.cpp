// Cantilever statics against the closed forms of beam theory.
#include <doctest/doctest.h>

#include "fem/assembly/Recovery.hpp"
#include "fem/static/Static.hpp"
#include "tests/Helpers.hpp"

using namespace beamrotor;
using namespace beamrotor::test;

// Hermite cubics reproduce the exact deflection of an end-loaded beam: only round-off remains
// (condition number ~1e6 for these models times machine epsilon ~1e-16).
constexpr double kHermiteRoundOff = 1e-10;

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
        CHECK(relError(r.displacement(line.nodes.back(), 1), -P * L * L * L / (3 * EI)) < kHermiteRoundOff);
        CHECK(relError(r.displacement(line.nodes.back(), 5), -P * L * L / (2 * EI)) < kHermiteRoundOff);
        CHECK(relError(r.reaction("root", Dof::uy), P) < kHermiteRoundOff);
        CHECK(relError(r.reaction("root", Dof::rz), P * L) < kHermiteRoundOff);
      }
      SUBCASE("tip moment") {
        Model m;
        const Line line = uniformBeam(m, L, sec, n);
        clamp(m, "root", line.nodes.front(), DofSet::planar());
        m.addLoad({line.nodes.back(), Dof::rz, M0});
        const StaticResult r = solveStatic(m);
        CHECK(relError(r.displacement(line.nodes.back(), 1), M0 * L * L / (2 * EI)) < kHermiteRoundOff);
        CHECK(relError(r.displacement(line.nodes.back(), 5), M0 * L / EI) < kHermiteRoundOff);
      }
    }
  }

  TEST_CASE("two loads on one dof add up: P1 + P2 at the tip") {
    // Superposition: the tip deflection under P1 and P2 on the same dof is (P1 + P2) L^3 / (3 EI).
    const double L = 2.0, P1 = -1500.0, P2 = 400.0;
    const auto sec = steelCircle(0.05);
    Model m;
    const Line line = uniformBeam(m, L, sec, 3);
    clamp(m, "root", line.nodes.front(), DofSet::planar());
    m.addLoad({line.nodes.back(), Dof::uy, P1});
    m.addLoad({line.nodes.back(), Dof::uy, P2});
    const StaticResult r = solveStatic(m);
    CHECK(relError(r.displacement(line.nodes.back(), 1), (P1 + P2) * L * L * L / (3 * sec->EIz())) <
          kHermiteRoundOff);
    CHECK(relError(r.reaction("root", Dof::uy), -(P1 + P2)) < kHermiteRoundOff);
  }

  TEST_CASE("3D cantilever, b != h, uniform load in each plane: deflection and moments") {
    // Clamped at x = 0, free at L, a uniform load q along local y (then z) of a 0.1 x 0.4
    // rectangle: tip deflection q L^4 / (8 E I) + q L^2 / (2 kappa G A) (the shear term for the
    // Timoshenko element only), with I and kappa of the plane that bends. Equilibrium of the part
    // [x, L] gives the stress resultants on the face with outward normal +x: V = q (L - x) and
    // M_z = q (L - x)^2 / 2 for a load along y, M_y = -q (L - x)^2 / 2 for a load along z
    // (dM_z/dx = -V_y, dM_y/dx = V_z). Hermite and interdependent-interpolation elements with
    // the consistent load are exact at the nodes, and recovery by equilibrium of each element is
    // exact inside it: round-off.
    const double L = 3.0, q = -4000.0;
    const auto sec = steelRectangle(0.1, 0.4);
    const double E = sec->material.E, G = sec->material.G, A = sec->A;
    const double nu = sec->material.nu, kappa = 10 * (1 + nu) / (12 + 11 * nu);
    for (BeamTheory theory : {BeamTheory::eulerBernoulli, BeamTheory::timoshenko})
      for (int axis : {1, 2}) {  // load along local (= global) y, then z
        CAPTURE(int(theory));
        CAPTURE(axis);
        const double I = axis == 1 ? 0.1 * std::pow(0.4, 3) / 12 : 0.4 * std::pow(0.1, 3) / 12;
        const double shear = theory == BeamTheory::timoshenko ? q * L * L / (2 * kappa * G * A) : 0;
        Model m;
        const int n = 4;
        const Line line = uniformBeam(m, L, sec, n, DofSet::frame3d(), {theory});
        for (Beam* b : line.beams) b->setDistributedLoad(q * Eigen::Vector3d::Unit(axis));
        clamp(m, "root", line.nodes.front(), DofSet::frame3d());
        const StaticResult r = solveStatic(m);
        const double tip = q * std::pow(L, 4) / (8 * E * I) + shear;
        CHECK(relError(r.displacement(line.nodes.back(), axis), tip) < kHermiteRoundOff);
        CHECK(std::abs(r.displacement(line.nodes.back(), 3 - axis)) < kHermiteRoundOff * std::abs(tip));
        // Stations every quarter of each element, ends included.
        const std::vector<BeamStation> stations = recoverBeamFields({m, r.displacement}, 4);
        REQUIRE(stations.size() == std::size_t(n * 5));
        for (std::size_t i = 0; i < stations.size(); ++i) {
          const BeamStation& st = stations[i];
          const double x = (double(i / 5) + 0.25 * double(i % 5)) * L / n;
          CHECK(std::abs(st.position.x() - x) < 1e-14 * L);
          const double V = q * (L - x), M = q * (L - x) * (L - x) / 2;
          const SectionForces& f = st.forces;
          CHECK(std::abs((axis == 1 ? f.Vy : f.Vz) - V) < kHermiteRoundOff * std::abs(q * L));
          CHECK(std::abs((axis == 1 ? f.Mz : -f.My) - M) < kHermiteRoundOff * std::abs(q * L * L));
          CHECK(std::abs(axis == 1 ? f.My : f.Mz) < kHermiteRoundOff * std::abs(q * L * L));
        }
      }
  }
}

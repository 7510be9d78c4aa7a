// Linear buckling of structures: a stepped column against its exact transcendental equation,
// a portal frame's sway against the alignment-chart equation (exact for it), and the reversed
// load's factors.
#include <doctest/doctest.h>

#include <cmath>

#include "fem/stability/Buckling.hpp"
#include "meshes/FrameBuilder.hpp"
#include "tests/Helpers.hpp"

using namespace beamrotor;
using namespace beamrotor::test;

TEST_SUITE("buckling") {
  TEST_CASE("stepped cantilever column: the exact transcendental equation") {
    // Fixed base, part 1 (EI1, length a) at the base, part 2 (EI2, length b) above, load P at
    // the free top. With k_i = sqrt(P / EI_i), the deflection delta (1 - cos k1 x) below the
    // step and delta + A sin k2 (L - x) above it (no moment at the top) meet with equal
    // deflection and slope when tan(k1 a) tan(k2 b) = k2 / k1 (Timoshenko and Gere, Theory of
    // Elastic Stability, sec. 2.10); the lowest root has both arguments below pi/2. The pump
    // rod's diameters and lengths: D1 = 120 mm over 0.575 m, D2 = 70 mm over 1.130 m.
    const double a = 0.575, b = 1.130;
    auto s1 = steelCircle(0.12), s2 = steelCircle(0.07);
    const double EI1 = s1->EIz(), EI2 = s2->EIz();
    const auto f = [&](double P) {
      const double k1 = std::sqrt(P / EI1), k2 = std::sqrt(P / EI2);
      return std::tan(k1 * a) * std::tan(k2 * b) - k2 / k1;
    };
    const double top = std::min(EI1 * std::pow(kPi / (2 * a), 2), EI2 * std::pow(kPi / (2 * b), 2));
    const double exact = bisectRoot(f, 1e-9 * top, top * (1 - 1e-12));
    // 16 + 32 elements: measured error 5.6e-9 (h^4); tolerance 1e-7.
    for (BeamTheory theory : {BeamTheory::eulerBernoulli}) {
      Model m;
      LineSpec spec;
      spec.dofs = DofSet::planar();
      spec.segments.push_back({a, s1, 16, 0, {theory}});
      spec.segments.push_back({b, s2, 32, 0, {theory}});
      spec.points = {{"base", 0}, {"top", a + b}};
      buildLine(m, spec);
      clamp(m, "base", m.node("base"), DofSet::planar());
      m.addLoad({m.node("top"), Dof::ux, -1.0});
      const BucklingResult r = solveBuckling(m);
      MESSAGE("stepped column: exact " << exact << " N, FE " << r.modes.at(0).factor
                                       << ", error " << relError(r.modes[0].factor, exact));
      CHECK(relError(r.modes.at(0).factor, exact) < 1e-7);
      // The mode: largest translation 1 at the free top, across the column.
      CHECK(r.modes[0].shape(m.node("top"), 1) == doctest::Approx(1).epsilon(1e-12));
    }
  }

  TEST_CASE("portal frame sway: the alignment-chart equation, exact for this frame") {
    // Fixed bases, columns h, beam span l, equal loads P on both column tops (beam
    // unloaded, so it carries no axial force). In sway both beam ends turn equally, so the
    // beam resists with 6 E Ib / l per end, the alignment chart's assumption; with G_top =
    // (E Ic / h) / (E Ib / l) and G_base = 0 (fixed) the chart's sway equation
    //   (G_A G_B x^2 - 36) / (6 (G_A + G_B)) = x / tan x,  x = pi / K
    // becomes tan x = -G x / 6, x in (pi/2, pi), and Pcr = x^2 E Ic / h^2 (AISC 360-16,
    // Commentary to Appendix 7, eq. C-A-7-2). The chart takes the columns as inextensible; in
    // the sway mode the beam's end shears stretch one column and shorten the other, which with
    // the real area (0.2 x 0.2 m) lowered the FE load by 6.3e-4 (measured). The columns here
    // keep their bending stiffness but get 1e6 times the area, which leaves that effect below
    // 1e-9.
    const double h = 4.0, l = 6.0;
    const auto square = steelRectangle(0.2, 0.2);
    auto column = std::make_shared<Section>(Section::general(
        "column", square->material, 1e6 * square->A, square->Iy, square->Iz, square->J, 0, 0, 0.2));
    auto beamSection = steelRectangle(0.15, 0.3);
    const double G = (column->EIz() / h) / (beamSection->EIz() / l);
    const double x = bisectRoot([&](double t) { return std::tan(t) + G * t / 6; },
                                kPi / 2 + 1e-9, kPi - 1e-12);
    const double exact = x * x * column->EIz() / (h * h);

    Model m;
    FrameSpec spec;
    spec.dofs = DofSet::planar();
    spec.joints = {{"A", Eigen::Vector3d(0, 0, 0)}, {"B", Eigen::Vector3d(0, h, 0)},
                   {"C", Eigen::Vector3d(l, h, 0)}, {"D", Eigen::Vector3d(l, 0, 0)}};
    spec.members.push_back({0, 1, {h, column, 16, 0, {}}, {}, {}});
    spec.members.push_back({1, 2, {l, beamSection, 16, 0, {}}, {}, {}});
    spec.members.push_back({3, 2, {h, column, 16, 0, {}}, {}, {}});
    const FrameMesh mesh = buildFrame(m, spec);
    clamp(m, "A", mesh.jointNodes[0], DofSet::planar());
    clamp(m, "D", mesh.jointNodes[3], DofSet::planar());
    m.addLoad({mesh.jointNodes[1], Dof::uy, -1.0});
    m.addLoad({mesh.jointNodes[2], Dof::uy, -1.0});
    BucklingOptions o;
    o.count = 2;
    const BucklingResult r = solveBuckling(m, o);
    MESSAGE("portal sway: exact " << exact << " N, FE " << r.modes.at(0).factor << ", error "
                                  << relError(r.modes[0].factor, exact));
    // Measured error 1.2e-6 (discretisation, 16 elements per member): tolerance 5e-6.
    CHECK(relError(r.modes.at(0).factor, exact) < 5e-6);
    // It is the sway mode: both column tops move the same way along x.
    const double topB = r.modes[0].shape(mesh.jointNodes[1], 0);
    const double topC = r.modes[0].shape(mesh.jointNodes[2], 0);
    CHECK(topB * topC > 0);
    CHECK(relError(topB, topC) < 1e-3);
    // The next mode (symmetric, no sway) lies higher.
    CHECK(r.modes.at(1).factor > 1.5 * r.modes[0].factor);
  }

  TEST_CASE("reversed load: negative factors; a load that compresses nothing has no positive one") {
    // A column fixed at both ends pulled by its load: it cannot buckle under that load; its
    // reverse is a compression with Pcr = 4 pi^2 EI / L^2, factor -Pcr / 1 N. 8 elements:
    // measured error 5.1e-4, as for the fixed-fixed column in the element tests (h^4).
    const double L = 2.0;
    auto sec = steelCircle(0.05);
    Model m;
    const Line line = uniformBeam(m, L, sec, 8);
    clamp(m, "base", line.nodes.front(), DofSet::planar());
    m.addSupport({"top", line.nodes.back(), {{Dof::uy, 0}, {Dof::rz, 0}}});
    m.addLoad({line.nodes.back(), Dof::ux, +1.0});
    BucklingOptions o;
    o.count = 2;
    o.reversed = true;
    const BucklingResult r = solveBuckling(m, o);
    CHECK(r.modes.empty());
    REQUIRE(!r.warnings.empty());
    REQUIRE(r.reversed.size() == 2);
    const double exact = -4 * kPi * kPi * sec->EIz() / (L * L);
    CHECK(relError(r.reversed[0].factor, exact) < 6e-4);
  }

  TEST_CASE("a large model takes the Lanczos path and agrees with the dense one") {
    // 150 elements (450 free dofs, above the dense limit of 200): pinned-pinned column,
    // modes n = 1, 2, 3 at n^2 pi^2 EI / L^2. The discretisation error grows as (n h)^4:
    // measured 2.1e-8 for mode 3, 3e-10 for mode 1; tolerance 5e-8.
    const double L = 3.0;
    auto sec = steelCircle(0.05);
    Model m;
    const Line line = uniformBeam(m, L, sec, 150);
    m.addSupport({"base", line.nodes.front(), {{Dof::ux, 0}, {Dof::uy, 0}}});
    m.addSupport({"top", line.nodes.back(), {{Dof::uy, 0}}});
    m.addLoad({line.nodes.back(), Dof::ux, -1.0});
    BucklingOptions o;
    o.count = 3;
    const BucklingResult r = solveBuckling(m, o);
    REQUIRE(r.modes.size() == 3);
    for (int n = 1; n <= 3; ++n)
      CHECK(relError(r.modes[n - 1].factor, n * n * kPi * kPi * sec->EIz() / (L * L)) < 5e-8);
  }
}

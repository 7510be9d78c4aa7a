// Tension-only and compression-only members: an X-braced panel whose compressed diagonal goes
// slack is a determinate truss (the tension diagonal alone carries the storey shear), and a
// compression-only prop under a cantilever lifts off when the load pulls the tip up.
#include <doctest/doctest.h>

#include <cmath>

#include "elements/Beam.hpp"
#include "fem/static/OneWayMembers.hpp"
#include "tests/Helpers.hpp"

using namespace beamrotor;
using namespace beamrotor::test;

namespace {

// Both checks are exact for the elements (straight Euler-Bernoulli beams, nodal values exact
// under nodal loads): round-off of a well-conditioned solve only.
constexpr double kExact = 1e-9;

// A beam from node a to node b of the model, pinned (rz released) at the ends asked.
Beam& addBar(Model& m, int a, int b, const std::shared_ptr<const Section>& s, bool pinStart,
             bool pinEnd, const std::string& name) {
  Beam& beam = m.add<Beam>(a, m.nodes()[a], b, m.nodes()[b], s, DofSet::planar());
  if (pinStart) beam.release(0, Dof::rz);
  if (pinEnd) beam.release(1, Dof::rz);
  m.addMember(name, {int(m.elements().size()) - 1});
  return beam;
}

constexpr double kWidth = 4.0, kHeight = 3.0;

// The X-braced panel: pinned bases A (0, 0) and B (width, 0), columns A-C and B-D, beam C-D,
// diagonals A-D and B-C, every joint pinned; lateral load H at C along x. The slack members
// are left out.
Model bracedPanel(double H, const std::vector<bool>& slack) {
  Model m;
  const int A = m.addNode({0, 0, 0}), B = m.addNode({kWidth, 0, 0});
  const int C = m.addNode({0, kHeight, 0}), D = m.addNode({kWidth, kHeight, 0});
  const auto frame = steelCircle(0.08), rod = steelCircle(0.02);
  addBar(m, A, C, frame, true, true, "left column");
  addBar(m, B, D, frame, true, true, "right column");
  addBar(m, C, D, frame, true, true, "beam");
  if (!slack[0]) addBar(m, A, D, rod, true, true, "diagonal AD");
  if (!slack[1]) addBar(m, B, C, rod, true, true, "diagonal BC");
  m.addSupport({"A", A, {{Dof::ux, 0}, {Dof::uy, 0}}});
  m.addSupport({"B", B, {{Dof::ux, 0}, {Dof::uy, 0}}});
  m.addLoad({C, Dof::ux, H});
  return m;
}

}  // namespace

TEST_SUITE("one-way members") {
  TEST_CASE("X-braced panel: the compressed diagonal goes slack, the other carries H / cos theta") {
    const std::vector<OneWayMember> diagonals{{"diagonal AD", MemberAction::tensionOnly},
                                              {"diagonal BC", MemberAction::tensionOnly}};
    const double H = 10e3;
    // With one diagonal the pin-jointed panel is determinate: the columns (vertical links)
    // carry no shear, so the diagonal's horizontal component N cos theta equals H whatever
    // the bars' axial stiffness EA.
    const double cosTheta = kWidth / std::hypot(kWidth, kHeight);
    for (const double sign : {1.0, -1.0}) {
      CAPTURE(sign);
      const OneWaySolution s = solveWithOneWayMembers(
          [&](const std::vector<bool>& slack) { return std::make_shared<const Model>(bracedPanel(sign * H, slack)); }, diagonals);
      // H along +x sways C and D to the right: A-D lengthens, B-C shortens; reversed, the
      // other way round.
      const int taut = sign > 0 ? 0 : 1, slack = 1 - taut;
      REQUIRE(s.result.oneWayMembers.size() == 2);
      CHECK_FALSE(s.result.oneWayMembers[taut].slack);
      CHECK(s.result.oneWayMembers[slack].slack);
      CHECK(s.result.oneWayMembers[slack].force == 0);
      CHECK(s.result.oneWayMembers[slack].elongation < 0);
      const double error = relError(s.result.oneWayMembers[taut].force, H / cosTheta);
      MESSAGE("tension diagonal force error: ", error);
      CHECK(error < kExact);
      // Starting from both diagonals in, one switch and a confirming solve.
      CHECK(s.iterations == 2);
    }
  }

  TEST_CASE("both diagonals in when they act both ways: neither is slack, they share H") {
    const std::vector<OneWayMember> diagonals{{"diagonal AD", MemberAction::both},
                                              {"diagonal BC", MemberAction::both}};
    const OneWaySolution s = solveWithOneWayMembers(
        [&](const std::vector<bool>& slack) { return std::make_shared<const Model>(bracedPanel(10e3, slack)); }, diagonals);
    CHECK_FALSE(s.result.oneWayMembers[0].slack);
    CHECK_FALSE(s.result.oneWayMembers[1].slack);
    // Horizontal equilibrium of the top: (N_AD - N_BC) cos theta = H (columns carry no shear).
    const double cosTheta = kWidth / std::hypot(kWidth, kHeight);
    CHECK(relError((s.result.oneWayMembers[0].force - s.result.oneWayMembers[1].force) * cosTheta, 10e3) < kExact);
    CHECK(s.result.oneWayMembers[1].force < 0);
  }

  TEST_CASE("a compression-only prop under a cantilever tip lifts off when the tip is pulled up") {
    // Cantilever O-T (length L, clamped at O) propped at T by a pinned vertical strut T-G
    // (length Ls, ground G pinned). Tip load P along y.
    const double L = 2.0, Ls = 1.0, P = 5e3;
    const auto beamSection = steelCircle(0.06), strutSection = steelCircle(0.01);
    auto build = [&](double load, const std::vector<bool>& slack) {
      auto model = std::make_shared<Model>();
      Model& m = *model;
      const int O = m.addNode({0, 0, 0}), T = m.addNode({L, 0, 0}), G = m.addNode({L, -Ls, 0});
      addBar(m, O, T, beamSection, false, false, "cantilever");
      if (!slack[0]) addBar(m, G, T, strutSection, true, true, "prop");
      clamp(m, "wall", O, DofSet::planar());
      m.addSupport({"ground", G, {{Dof::ux, 0}, {Dof::uy, 0}}});
      m.addLoad({T, Dof::uy, load});
      return std::shared_ptr<const Model>(model);
    };
    const std::vector<OneWayMember> prop{{"prop", MemberAction::compressionOnly}};
    const double EI = beamSection->EIz(), k = strutSection->EA() / Ls;

    SUBCASE("pulled up: the prop lifts off and the tip deflects as a free cantilever's") {
      const OneWaySolution s = solveWithOneWayMembers(
          [&](const std::vector<bool>& slack) { return build(P, slack); }, prop);
      CHECK(s.result.oneWayMembers[0].slack);
      CHECK(s.result.oneWayMembers[0].elongation > 0);
      const double tip = s.result.displacement(1, 1);
      MESSAGE("lifted-off tip error: ", relError(tip, P * L * L * L / (3 * EI)));
      CHECK(relError(tip, P * L * L * L / (3 * EI)) < kExact);
    }
    SUBCASE("pushed down: the prop bears, with the force of a cantilever on a spring EA/Ls") {
      const OneWaySolution s = solveWithOneWayMembers(
          [&](const std::vector<bool>& slack) { return build(-P, slack); }, prop);
      CHECK_FALSE(s.result.oneWayMembers[0].slack);
      // Tip compatibility: (P - R) L^3 / (3 EI) = R / k.
      const double R = P / (1 + 3 * EI / (k * L * L * L));
      MESSAGE("prop force error: ", relError(-s.result.oneWayMembers[0].force, R));
      CHECK(relError(-s.result.oneWayMembers[0].force, R) < kExact);
      CHECK(s.iterations == 1);
    }
  }

  TEST_CASE("a one-way member of several elements is refused with its name") {
    auto build = [](const std::vector<bool>&) {
      auto model = std::make_shared<Model>();
      Model& m = *model;
      const Line line = uniformBeam(m, 2.0, steelCircle(0.05), 2);
      m.addMember("rod", {0, 1});
      clamp(m, "left", line.nodes.front(), DofSet::planar());
      return std::shared_ptr<const Model>(model);
    };
    CHECK_THROWS_WITH_AS(
        solveWithOneWayMembers(build, {{"rod", MemberAction::tensionOnly}}),
        doctest::Contains("'rod' acts one way only"), std::invalid_argument);
  }
}

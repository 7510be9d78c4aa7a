// Temperature loads on beams (issue 47): a uniform change dT imposes the axial strain alpha dT,
// a rise dTy (dTz) through the depth h the curvature alpha dTy / h. Checked against the
// closed forms of restrained and free members: a bar fixed at both ends carries
// N = -E A alpha dT, a beam clamped at both ends the constant moment E I alpha dTy / h, a free
// bar lengthens by alpha dT L with no force, a cantilever curls into the circle of curvature
// alpha dTy / h, a propped cantilever carries 3/2 E I alpha dTy / h at its clamp (compatibility
// of the released cantilever's end rotation; e.g. Ghali, Neville and Brown, Structural
// Analysis, 6th ed., sec. 4.7). Each along the whole member, between the nodes too.
#include <doctest/doctest.h>

#include <cmath>
#include <memory>
#include <string>
#include <vector>

#include "elements/Beam.hpp"
#include "fem/assembly/Recovery.hpp"
#include "fem/model/Loading.hpp"
#include "fem/model/Model.hpp"
#include "fem/static/Static.hpp"
#include "problems/deck/parse/DeckError.hpp"
#include "tests/problems/DeckTestSupport.hpp"

using namespace beamrotor;

namespace {

constexpr double kE = 210e9, kAlpha = 12e-6, kL = 4;
constexpr double kB = 0.1, kH = 0.2;  // a rectangle: width (local z) by depth (local y)

std::shared_ptr<const Section> rectangle() {
  Material steel = Material::fromEnu("steel", kE, 0.3, 7850);
  steel.alpha = kAlpha;
  return std::make_shared<const Section>(Section::rectangle("bar", steel, kB, kH));
}

/// A straight 3D member of `n` beams from the origin along `direction` (length kL), its
/// nodes in order; every beam imposes `strain` unless a Loading carries it instead.
struct Member {
  Model model;
  std::vector<int> nodes;
  Member(int n, const Eigen::Vector3d& direction, BeamTheory theory, const Eigen::Vector3d& strain) {
    const auto section = rectangle();
    const Eigen::Vector3d d = direction.normalized();
    for (int i = 0; i <= n; ++i) nodes.push_back(model.addNode(d * kL * i / n));
    for (int i = 0; i < n; ++i) {
      Beam& b = model.add<Beam>(nodes[i], nodes[i + 1], d, kL / n, section, DofSet::frame3d(),
                                BeamOptions{theory});
      if (!strain.isZero()) b.setImposedStrain(strain);
    }
  }
  void fix(int node, const std::string& name, std::vector<Dof> dofs = {kAllDofs.begin(), kAllDofs.end()}) {
    Support s{name, node, {}};
    for (Dof d : dofs) s.dofs.push_back({d, 0});
    model.addSupport(s);
  }
};

// Restrained members and free ones solve exactly (end-loaded elements; the imposed strain's
// clamped solution is zero displacement): round-off of a few solves, relative 1e-9.
constexpr double kExact = 1e-9;

}  // namespace

TEST_SUITE("temperature") {
  TEST_CASE("a section's thermal strain: alpha dT on the axis, alpha dT / h across each depth") {
    const auto s = rectangle();
    const Eigen::Vector3d e = thermalStrain(*s, 30, 20, -10);
    CHECK(e[0] == doctest::Approx(kAlpha * 30).epsilon(1e-15));
    CHECK(e[1] == doctest::Approx(kAlpha * -10 / kB).epsilon(1e-15));  // rotation rate ry'
    CHECK(e[2] == doctest::Approx(-kAlpha * 20 / kH).epsilon(1e-15));  // rz': hot +y sags
    // A general section without its depth cannot take a gradient, a uniform change it can.
    const Section bare = Section::general("g", s->material, 1e-3, 1e-6, 1e-6, 1e-6, 0, 0, 0);
    CHECK(thermalStrain(bare, 30, 0, 0)[0] == doctest::Approx(kAlpha * 30));
    CHECK_THROWS_AS(thermalStrain(bare, 0, 20, 0), std::invalid_argument);
  }

  TEST_CASE("fixed at both ends: N = -E A alpha dT and the moments E I alpha dT / h everywhere") {
    const double dT = 40, dTy = 25, dTz = -15;
    const auto s = rectangle();
    for (BeamTheory theory : {BeamTheory::eulerBernoulli, BeamTheory::timoshenko}) {
      CAPTURE(int(theory));
      Member m(5, Eigen::Vector3d(1, 2, -0.5), theory, thermalStrain(*s, dT, dTy, dTz));
      m.fix(m.nodes.front(), "A");
      m.fix(m.nodes.back(), "B");
      const StaticResult r = solveStatic(m.model);
      CHECK(r.displacement.cwiseAbs().maxCoeff() == 0.0);  // nothing moves: no free dof loaded
      const double N = -kE * s->A * kAlpha * dT, Mz = kE * s->Iz * kAlpha * dTy / kH,
                   My = -kE * s->Iy * kAlpha * dTz / kB;
      for (const BeamStation& st : recoverBeamFields({m.model, r.displacement}, 4)) {
        CHECK(st.forces.N == doctest::Approx(N).epsilon(kExact));
        CHECK(st.forces.Mz == doctest::Approx(Mz).epsilon(kExact));
        CHECK(st.forces.My == doctest::Approx(My).epsilon(kExact));
        CHECK(std::abs(st.forces.Vy) + std::abs(st.forces.Vz) <= kExact * std::abs(Mz));
        // The stress is E times the restrained strain: E alpha (|dT| + |dTy| / 2 + |dTz| / 2)
        // at the corner where all three add.
        CHECK(st.stress == doctest::Approx(kE * kAlpha * (dT + dTy / 2 - dTz / 2)).epsilon(kExact));
      }
      // The supports push the bar's ends together with E A alpha dT.
      const Eigen::Vector3d axis = Eigen::Vector3d(1, 2, -0.5).normalized();
      const Eigen::Vector3d pushA(r.reaction("A", Dof::ux), r.reaction("A", Dof::uy),
                                  r.reaction("A", Dof::uz));
      CHECK(pushA.dot(axis) == doctest::Approx(-N).epsilon(kExact));
    }
  }

  TEST_CASE("a free bar lengthens by alpha dT L, a cantilever curls, neither carries a force") {
    const double dT = 40, dTy = 25;
    const auto s = rectangle();
    for (BeamTheory theory : {BeamTheory::eulerBernoulli, BeamTheory::timoshenko}) {
      CAPTURE(int(theory));
      // Along x: local y is global y, so the rise towards +y curls the tip down (-y).
      Member m(3, Eigen::Vector3d::UnitX(), theory, thermalStrain(*s, dT, dTy, 0));
      m.fix(m.nodes.front(), "A");
      const StaticResult r = solveStatic(m.model);
      const double kappa = kAlpha * dTy / kH;
      for (const BeamStation& st : recoverBeamFields({m.model, r.displacement}, 5)) {
        const double x = st.position.x();
        CAPTURE(x);
        CHECK(st.displacement[0] == doctest::Approx(kAlpha * dT * x).epsilon(kExact));
        CHECK(st.displacement[1] == doctest::Approx(-kappa * x * x / 2).epsilon(kExact));
        CHECK(st.displacement[5] == doctest::Approx(-kappa * x).epsilon(kExact));
        CHECK(std::abs(st.forces.N) <= kExact * kE * s->A * kAlpha * dT);
        CHECK(std::abs(st.forces.Mz) <= kExact * kE * s->Iz * kappa);
        CHECK(st.stress <= kExact * kE * kAlpha * dT);
      }
      CHECK(std::abs(r.reaction("A", Dof::ux)) <= kExact * kE * s->A * kAlpha * dT);
    }
  }

  TEST_CASE("a propped cantilever: 3/2 E I alpha dT / h at the clamp, also through a hinge") {
    const double dTy = 30;
    const auto s = rectangle();
    const double M0 = 1.5 * kE * s->Iz * kAlpha * dTy / kH;
    for (bool hinged : {false, true}) {
      CAPTURE(hinged);
      Member m(4, Eigen::Vector3d::UnitX(), BeamTheory::eulerBernoulli, thermalStrain(*s, 0, dTy, 0));
      m.fix(m.nodes.front(), "A");
      // The prop: uy held; its end rotation free, either at the node or as the element's
      // released end (a hinge, whose rotation the condensation recovers).
      m.fix(m.nodes.back(), "B", {Dof::ux, Dof::uy, Dof::uz, Dof::rx, Dof::ry});
      if (hinged) static_cast<Beam&>(*m.model.elements().back()).release(1, Dof::rz);
      const StaticResult r = solveStatic(m.model);
      // The clamp's moment: the restrained gradient's E I alpha dTy / h less the prop's
      // R L, R = 3 E I kappa / (2 L) (the cantilever's tip rotation kappa L undone).
      for (const BeamStation& st : recoverBeamFields({m.model, r.displacement}, 3)) {
        const double x = st.position.x();
        CAPTURE(x);
        // Mz(x) = M0 (1 - x / L): the prop's reaction R = M0 / L acting through the span.
        CHECK(st.forces.Mz == doctest::Approx(M0 * (1 - x / kL)).epsilon(kExact).scale(M0));
      }
      CHECK(std::abs(r.reaction("B", Dof::uy)) == doctest::Approx(M0 / kL).epsilon(kExact));
    }
  }

  TEST_CASE("a temperature load case: the same as the beams' own, and factored in combinations") {
    const double dT = 40, dTy = 25;
    const auto s = rectangle();
    const Eigen::Vector3d strain = thermalStrain(*s, dT, dTy, 0);
    Member own(4, Eigen::Vector3d(1, 1, 0), BeamTheory::timoshenko, strain);
    Member bare(4, Eigen::Vector3d(1, 1, 0), BeamTheory::timoshenko, Eigen::Vector3d::Zero());
    for (Member* m : {&own, &bare}) {
      m->fix(m->nodes.front(), "A");
      m->fix(m->nodes[2], "mid", {Dof::uy});
    }
    std::vector<std::pair<int, ElementSpanLoad>> span;
    for (int e = 0; e < 4; ++e) span.emplace_back(e, ElementSpanLoad{Eigen::Vector3d::Zero(), Eigen::Vector3d::Zero(), strain});
    const auto heat = std::make_shared<const Loading>(std::vector<NodalLoad>{}, span);
    const Loading twice = Loading::combination({{heat, 1.5}, {heat, 0.5}});
    const StaticResult a = solveStatic(own.model);
    const std::vector<StaticResult> b = solveLoadings(bare.model, {heat.get(), &twice});
    const double scale = a.displacement.cwiseAbs().maxCoeff();
    CHECK(scale > 0);
    CHECK((b[0].displacement - a.displacement).cwiseAbs().maxCoeff() <= kExact * scale);
    CHECK((b[1].displacement - 2 * a.displacement).cwiseAbs().maxCoeff() <= 2 * kExact * scale);
    const auto ownStations = recoverBeamFields({own.model, a.displacement}, 3);
    const auto caseStations = recoverBeamFields({bare.model, b[1].displacement, &twice}, 3);
    for (std::size_t i = 0; i < ownStations.size(); ++i) {
      CHECK(caseStations[i].forces.Mz ==
            doctest::Approx(2 * ownStations[i].forces.Mz).epsilon(kExact).scale(kE * s->Iz * kAlpha * dTy / kH));
      CHECK(caseStations[i].forces.N ==
            doctest::Approx(2 * ownStations[i].forces.N).epsilon(kExact).scale(kE * s->A * kAlpha * dT));
    }
  }
}

TEST_SUITE("temperature") {
  // A portal frame whose beam heats up: the deck reads alpha and the temperatures with their
  // units, and the fixed-fixed bar's closed form holds through the whole run.
  std::string barDeck(const std::string& loads, const std::string& alpha = "alpha: 12e-6/K") {
    return "model: {dimension: planar}\n"
           "materials: [{name: steel, E: 210 GPa, nu: 0.3, " + alpha + "}]\n"
           "sections: [{name: bar, shape: rectangle, b: 100 mm, h: 200 mm}]\n"
           "nodes: [{name: A, at: [0, 0]}, {name: B, at: [4 m, 0]}]\n"
           "members: [{name: bar, from: A, to: B, section: bar, elements: 4}]\n"
           "supports: [{name: A, at: A, fix: clamped}, {name: B, at: B, fix: clamped}]\n" +
           loads + "analyses: [{type: static}]\n";
  }

  TEST_CASE("a deck's temperature load: E A alpha dT and E I alpha dT / h, in a load case too") {
    const Study s = test::solveDeckText(
        barDeck("loads: [{type: temperature, dT: 40 K, dT_y: 25 K}]\n"
                "load_cases: [{name: heat, loads: [{type: temperature, dT: 40 K}]}]\n"
                "combinations: [{name: hot, factors: {heat: 1.5}}]\n"),
        "bar.yaml");
    const RunResult& run = *s.run;
    const double A = 0.1 * 0.2, EA = kE * A;
    CHECK(test::staticReaction(run, "A", Dof::ux) == doctest::Approx(EA * kAlpha * 40).epsilon(kExact));
    CHECK(test::staticReaction(run, "A", Dof::rz) ==
          doctest::Approx(-kE * 0.1 * std::pow(0.2, 3) / 12 * kAlpha * 25 / 0.2).epsilon(kExact));
    for (const CaseOutcome& c : casesOf(run.analyses.front()))
      CHECK(c.statics.reaction("A", Dof::ux) ==
            doctest::Approx((c.name == "hot" ? 1.5 : 1.0) * EA * kAlpha * 40).epsilon(kExact));
  }

  TEST_CASE("a temperature load is refused without alpha, without a depth, or in the wrong unit") {
    CHECK(std::string(test::readingError(barDeck("loads: [{type: temperature, dT: 40}]\n", "rho: 7850"),
                                         "bar.yaml").what())
              .find("give it alpha") != std::string::npos);
    CHECK(std::string(test::readingError(barDeck("loads: [{type: temperature, dT: 40 mm}]\n"),
                                         "bar.yaml").what())
              .find("temperature difference") != std::string::npos);
    CHECK(std::string(test::readingError(barDeck("loads: [{type: temperature, dT_z: 4}]\n"),
                                         "bar.yaml").what())
              .find("dT_z bends about ry") != std::string::npos);
    CHECK(std::string(test::readingError(barDeck("loads: [{type: temperature}]\n"), "bar.yaml").what())
              .find("at least one of dT") != std::string::npos);
  }
}

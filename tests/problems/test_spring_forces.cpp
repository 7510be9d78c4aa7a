// Forces of springs, bearings and contacts (support-like parts that are not supports): a
// cantilever propped by a spring at its tip, under a tip load and a uniform load, against the
// closed forms of compatibility (the tip deflection of the cantilever under the load and the
// spring force equals the spring's own stretch); the same in load cases and a combination (the
// factored sum) and their envelope over the combinations; a contact's force; a shaft's bearings; and each as it reaches results.json,
// the springs CSV, the summary and a check quantity (`reaction NAME DOF`).
#include <doctest/doctest.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>

#include <vtkDataArray.h>
#include <vtkNew.h>
#include <vtkPointData.h>
#include <vtkUnstructuredGrid.h>
#include <vtkXMLUnstructuredGridReader.h>

#include "problems/deck/parse/DeckError.hpp"
#include "problems/output/JsonWriter.hpp"
#include "problems/run/Study.hpp"
#include "tests/Helpers.hpp"
#include "tests/problems/DeckTestSupport.hpp"

using namespace beamrotor;

namespace {

// A cantilever of length L, clamped at A, EI = E I; its tip stiffness is 3 EI / L^3.
// Euler-Bernoulli elements under nodal and uniform loads (consistent nodal loads) are exact at
// the nodes, so the closed forms hold to round-off.
constexpr double kE = 210e9, kI = 8356e-8, kL = 4;
constexpr double kEI = kE * kI, kTip = 3 * kEI / (kL * kL * kL);
constexpr double kP = 10e3, kQ = 3e3;

/// The cantilever A-B with `attachments` (springs:, contacts: ...) and `rest` (loads, cases,
/// analyses, checks).
std::string cantilever(const std::string& attachments, const std::string& rest) {
  std::ostringstream d;
  d.precision(17);
  d << "model: {dimension: planar}\n"
    << "materials: [{name: steel, E: " << kE << ", nu: 0.3}]\n"
    << "sections: [{name: beam, shape: general, A: 53.8e-4, I: " << kI
    << ", J: 1e-6, depth: 0.3, width: 0.15}]\n"
    << "nodes: [{name: A, at: [0, 0]}, {name: B, at: [" << kL << ", 0]}]\n"
    << "members: [{name: beam, from: A, to: B, section: beam, elements: 4}]\n"
    << "supports: [{name: A, at: A, fix: clamped}]\n"
    << attachments << rest;
  return d.str();
}

std::string number(double v) {
  std::ostringstream s;
  s.precision(17);
  s << v;
  return s.str();
}

/// Force a tip spring of stiffness k exerts on the cantilever under a tip load P (downward):
/// the tip moves P / (k + kTip) down, the spring pushes back k times that.
double tipLoadSpringForce(double k, double P) { return P * k / (k + kTip); }

/// The same under a uniform load q (downward): the free tip would move q L^4 / (8 EI); the
/// spring force R closes it, R (L^3 / (3 EI) + 1 / k) = q L^4 / (8 EI).
double uniformLoadSpringForce(double k, double q) {
  return q * std::pow(kL, 4) / (8 * kEI) / (1 / kTip + 1 / k);
}

const RunResult& onlyRun(const Study& s) {
  const auto runs = test::runsOf(s);
  REQUIRE(runs.size() == 1);
  return *runs.front();
}

const CaseOutcome& caseOf(const RunResult& run, const std::string& name) {
  for (const CaseOutcome& c : casesOf(run.analyses.front()))
    if (c.name == name) return c;
  FAIL("no case " << name);
  throw 0;
}

}  // namespace

TEST_SUITE("spring forces") {
  // Exact method (see above): the measured differences are ~1e-15 relative; 1e-10 leaves
  // room for other platforms' round-off.
  constexpr double kExact = 1e-10;

  TEST_CASE("a spring propping a cantilever's tip carries P k / (k + 3 EI / L^3)") {
    const double k = 2 * kTip;
    const std::string deck = cantilever(
        "springs: [{name: prop, at: B, dof: uy, k: " + number(k) + "}, {at: B, dof: rz, k: 1}]\n",
        "loads: [{type: point, at: B, fy: " + number(-kP) +
            "}]\n"
            "checks: [{name: prop, quantity: reaction prop fy, reference: " +
            number(tipLoadSpringForce(k, kP)) + ", tolerance: 1e-6}]\n");  // see below
    const Study s = test::solveDeckText(deck, "prop.yaml");
    const RunResult& run = onlyRun(s);
    const StaticResult& r = *staticsOf(run.analyses.front());
    const double F = r.reaction("prop", Dof::uy);
    MESSAGE("spring force " << F << " N, closed form " << tipLoadSpringForce(k, kP));
    // The rotational spring of 1 N m/rad barely changes the tip: it is part of the reference.
    // Its force is -1 * rz(B) exactly; the uy spring's closed form treats it as absent, which
    // moves the answer by ~ 1 / (EI / L) = 2e-7 relative: checked against compatibility then.
    CHECK(F == doctest::Approx(tipLoadSpringForce(k, kP)).epsilon(1e-6));
    const int tip = run.model->node("B");
    CHECK(F == doctest::Approx(-k * r.displacement(tip, int(Dof::uy))).epsilon(kExact));
    CHECK(r.reaction("spring2", Dof::rz) ==
          doctest::Approx(-1.0 * r.displacement(tip, int(Dof::rz))).epsilon(kExact));
    // Equilibrium: the clamp and the spring hold the load together.
    CHECK(r.reaction("A", Dof::uy) + F == doctest::Approx(kP).epsilon(kExact));
    CHECK(test::checkAllPass(s) == 1);

    const Json doc = runJson(run);
    const Json& springs = doc["analyses"][0]["springs"];
    CHECK(springs["prop"]["fy"].get<double>() == F);
    CHECK(springs["spring2"].contains("mz"));
  }

  TEST_CASE("a spring's force in load cases and a combination is the factored sum") {
    const double k = 0.5 * kTip;
    const std::string deck = cantilever(
        "springs: [{name: prop, at: B, dof: uy, k: " + number(k) + "}]\n",
        "load_cases:\n"
        "  - {name: tip, loads: [{type: point, at: B, fy: " + number(-kP) + "}]}\n"
        "  - {name: udl, loads: [{type: distributed, member: beam, qy: " + number(-kQ) + "}]}\n"
        "combinations: [{name: ULS, factors: {tip: 1.35, udl: 1.5}}]\n"
        "checks: [{name: ULS prop, quantity: reaction prop fy, case: ULS, reference: " +
            number(1.35 * tipLoadSpringForce(k, kP) + 1.5 * uniformLoadSpringForce(k, kQ)) +
            ", tolerance: 1e-9}]\n");
    const Study s = test::solveDeckText(deck, "prop_cases.yaml");
    const RunResult& run = onlyRun(s);
    const double tip = caseOf(run, "tip").statics.reaction("prop", Dof::uy);
    const double udl = caseOf(run, "udl").statics.reaction("prop", Dof::uy);
    const double uls = caseOf(run, "ULS").statics.reaction("prop", Dof::uy);
    MESSAGE("tip " << tip << ", udl " << udl << ", ULS " << uls);
    CHECK(tip == doctest::Approx(tipLoadSpringForce(k, kP)).epsilon(kExact));
    CHECK(udl == doctest::Approx(uniformLoadSpringForce(k, kQ)).epsilon(kExact));
    CHECK(uls == doctest::Approx(1.35 * tip + 1.5 * udl).epsilon(kExact));
    CHECK(test::checkAllPass(s) == 1);

    // results.json's cases and the cases CSV carry it under the spring's name.
    const Json doc = runJson(run);
    bool found = false;
    for (const Json& c : doc["analyses"][0]["cases"])
      if (c["name"] == "ULS") {
        CHECK(c["springs"]["prop"]["fy"].get<double>() == uls);
        found = true;
      }
    CHECK(found);
  }

  TEST_CASE("the envelope gives each spring's largest and smallest force and its combination") {
    // k = 3 EI / L^3: the spring carries P / 2 of a tip load and, of a uniform load q (here
    // upward, lifting the tip off the spring), 3 q L / 16 pulling down.
    const std::string deck = cantilever(
        "springs: [{name: prop, at: B, dof: uy, k: " + number(kTip) + "}]\n",
        "load_cases:\n"
        "  - {name: tip, loads: [{type: point, at: B, fy: " + number(-kP) + "}]}\n"
        "  - {name: lift, loads: [{type: distributed, member: beam, qy: " + number(kQ) + "}]}\n"
        "combinations:\n"
        "  - {name: push, factors: {tip: 1.35}}\n"
        "  - {name: pull, factors: {tip: 1.0, lift: 3.0}}\n");
    const double tip = kP / 2, lift = -3 * kQ * kL / 16;  // 5000 N and -2250 N
    CHECK(tip == doctest::Approx(tipLoadSpringForce(kTip, kP)).epsilon(kExact));
    CHECK(-lift == doctest::Approx(uniformLoadSpringForce(kTip, kQ)).epsilon(kExact));
    // By hand: push 1.35 * 5000 = 6750 N, pull 5000 - 3 * 2250 = -1750 N.
    const double push = 1.35 * tip, pull = 1.0 * tip + 3.0 * lift;
    const Study s = test::solveDeckText(deck, "prop_envelope.yaml");
    const Json doc = runJson(onlyRun(s));
    const Json& env = doc["analyses"][0]["envelope"];
    REQUIRE(env.contains("springs"));
    const Json& fy = env["springs"]["prop"]["fy"];
    MESSAGE("envelope of prop fy: " << fy.dump());
    CHECK(fy["max"]["value"].get<double>() == doctest::Approx(push).epsilon(kExact));
    CHECK(fy["max"]["case"] == "push");
    CHECK(fy["min"]["value"].get<double>() == doctest::Approx(pull).epsilon(kExact));
    CHECK(fy["min"]["case"] == "pull");
    // The clamp's reaction is enveloped beside it: the load less the spring's share.
    CHECK(env["reactions"]["A"]["fy"]["max"]["value"].get<double>() ==
          doctest::Approx(1.35 * (kP - tip)).epsilon(kExact));

    // The summary's envelope lists the spring with both extremes and their combinations.
    const auto dir = test::scratchDir("spring-envelope");
    std::ofstream(dir / "prop.yaml") << deck;
    const auto p = test::runBeamrotor({"solve", (dir / "prop.yaml").string(), "--out",
                                       (dir / "out").string(), "--charts", "none"});
    REQUIRE_MESSAGE(p.exitCode == 0, p.err);
    const auto block = p.out.find("envelope over the combinations");
    REQUIRE(block != std::string::npos);
    const std::string envelope = p.out.substr(block);
    MESSAGE(envelope);
    CHECK(envelope.find("springs and bearings (N, N m):") != std::string::npos);
    CHECK(envelope.find("prop") != std::string::npos);
    CHECK(envelope.find("fy 6750 [push] / -1750 [pull]") != std::string::npos);
    std::filesystem::remove_all(dir);
  }

  TEST_CASE("a contact's force is a check quantity: P - 3 EI gap / L^3 once it closes") {
    const double gap = 0.5 * kP / kTip;  // the free tip would move twice the gap
    const std::string deck = cantilever(
        "contacts: [{name: stop, at: B, dof: uy, min: " + number(-gap) + "}]\n",
        "loads: [{type: point, at: B, fy: " + number(-kP) +
            "}]\n"
            "checks: [{name: stop, quantity: reaction stop fy, reference: " +
            number(kP - kTip * gap) + ", tolerance: 1e-9}]\n");
    const Study s = test::solveDeckText(deck, "stop.yaml");
    const StaticResult& r = *staticsOf(onlyRun(s).analyses.front());
    CHECK(r.reaction("stop", Dof::uy) == doctest::Approx(kP / 2).epsilon(kExact));
    CHECK(test::checkAllPass(s) == 1);
  }

  TEST_CASE("a shaft on two bearings under a central load: each bearing carries half") {
    // Statics by symmetry (equal bearings at equal distances): P / 2 in each direction, exact
    // but for round-off; the bearings' stiffnesses differ between y and z, which must not
    // matter.
    const std::string deck =
        "model: {dimension: lateral}\n"
        "materials: [{name: steel, E: 210e9, nu: 0.3, rho: 7850}]\n"
        "sections: [{name: s, shape: circle, D: 0.05}]\n"
        "segments: [{name: shaft, length: 1, section: s, elements: 4}]\n"
        "points: [{name: mid, at: 0.5}]\n"
        "bearings:\n"
        "  - {name: A, at: start, kxx: 1e8, kyy: 2e8}\n"
        "  - {name: B, at: end, kxx: 1e8, kyy: 2e8}\n"
        "loads: [{type: point, at: mid, fy: -1000, fz: 400}]\n"
        "analyses: [{type: static}]\n"
        "checks:\n"
        "  - {name: A, quantity: reaction A fy, reference: 500, tolerance: 1e-9}\n"
        "  - {name: B, quantity: reaction B uz, reference: -200, tolerance: 1e-9}\n";
    const Study s = test::solveDeckText(deck, "bearings.yaml");
    const StaticResult& r = *staticsOf(onlyRun(s).analyses.front());
    for (const char* bearing : {"A", "B"}) {
      CHECK(r.reaction(bearing, Dof::uy) == doctest::Approx(500).epsilon(kExact));
      CHECK(r.reaction(bearing, Dof::uz) == doctest::Approx(-200).epsilon(kExact));
    }
    CHECK(test::checkAllPass(s) == 2);
  }

  TEST_CASE("the springs CSV and the summary list each spring's force") {
    const std::string deck = cantilever(
        "springs: [{name: prop, at: B, dof: uy, k: " + number(kTip) + "}]\n",
        "loads: [{type: point, at: B, fy: " + number(-kP) + "}]\n");
    const auto dir = test::scratchDir("spring-forces");
    std::ofstream(dir / "prop.yaml") << deck;
    const auto p = test::runBeamrotor({"solve", (dir / "prop.yaml").string(), "--out",
                                       (dir / "out").string(), "--charts", "none"});
    REQUIRE_MESSAGE(p.exitCode == 0, p.err);
    // k = 3 EI / L^3: the spring takes half the load.
    CHECK(p.out.find("springs and bearings (force on the structure") != std::string::npos);
    CHECK(p.out.find("prop") != std::string::npos);
    const auto rows = test::csvCells(dir / "out" / "static_springs.csv");
    REQUIRE(rows.size() == 2);
    const auto& header = rows.front();
    // Text cells are quoted.
    CHECK(rows[1][test::csvColumn(header, "spring")] == "prop");
    CHECK(rows[1][test::csvColumn(header, "at")] == "B");
    CHECK(rows[1][test::csvColumn(header, "component")] == "fy");
    CHECK(std::stod(rows[1][test::csvColumn(header, "force")]) ==
          doctest::Approx(kP / 2).epsilon(kExact));
    // The support takes the other half: the reactions CSV in the same columns, and both as
    // VTK point data whose sums balance the load (equilibrium), each half at one node.
    const auto reactions = test::csvCells(dir / "out" / "static_reactions.csv");
    REQUIRE(reactions.size() >= 2);
    double fy = 0;
    for (std::size_t i = 1; i < reactions.size(); ++i)
      if (reactions[i][test::csvColumn(reactions.front(), "component")] == "fy")
        fy += std::stod(reactions[i][test::csvColumn(reactions.front(), "force")]);
    CHECK(fy == doctest::Approx(kP / 2).epsilon(kExact));
    vtkNew<vtkXMLUnstructuredGridReader> reader;
    reader->SetFileName((dir / "out" / "static.vtu").string().c_str());
    reader->Update();
    for (const char* array : {"reaction_force", "spring_force"}) {
      CAPTURE(array);
      vtkDataArray* f = reader->GetOutput()->GetPointData()->GetArray(array);
      REQUIRE(f != nullptr);
      double sum = 0;
      int loaded = 0;
      for (vtkIdType n = 0; n < f->GetNumberOfTuples(); ++n) {
        sum += f->GetComponent(n, 1);
        loaded += f->GetComponent(n, 1) != 0;
      }
      CHECK(sum == doctest::Approx(kP / 2).epsilon(kExact));
      CHECK(loaded == 1);
    }
    CHECK(reader->GetOutput()->GetPointData()->GetArray("reaction_moment") != nullptr);
    std::filesystem::remove_all(dir);
  }

  TEST_CASE("a reaction check names a support, spring, bearing or contact along one of its dofs") {
    const std::string springs = "springs: [{name: prop, at: B, dof: uy, k: 1e6}]\n";
    const auto refused = [&](const std::string& quantity, const std::string& phrase) {
      const DeckError e = test::readingError(
          cantilever(springs, "loads: [{type: point, at: B, fy: -1}]\n"
                              "checks: [{name: c, quantity: " + quantity +
                                  ", reference: 1, tolerance: 1}]\n"),
          "bad.yaml");
      INFO(e.what());
      CHECK(std::string(e.what()).find(phrase) != std::string::npos);
    };
    refused("reaction prop fx", "spring 'prop' acts along uy only, not ux");
    refused("reaction pro fy", "no support, spring, bearing or contact named 'pro'");
  }
}

// Units on deck numbers (issue 16): every dimension a field can have, a deck in mm, kN and MPa
// against its SI twin, mismatches refused naming the field and both dimensions, expressions
// and command-line overrides with units, and the plausibility warnings.
#include <doctest/doctest.h>
#include <muParser.h>
#include <yaml-cpp/yaml.h>

#include <algorithm>
#include <cctype>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <numbers>
#include <set>
#include <string>
#include <vector>

#include "problems/deck/DeckReader.hpp"
#include "problems/deck/parse/DeckSource.hpp"
#include "problems/deck/parse/Expression.hpp"
#include "problems/deck/parse/ExpressionFunctions.hpp"
#include "problems/deck/structure/MaterialPlausibility.hpp"
#include "problems/deck/study/Overrides.hpp"
#include "problems/deck/parse/SceneFunctions.hpp"
#include "problems/deck/study/SweepOption.hpp"
#include "problems/run/Study.hpp"
#include "tests/Helpers.hpp"
#include "tests/problems/DeckTestSupport.hpp"

using namespace beamrotor;

namespace {

/// A cantilever with a tip load, a tip moment, a uniform load and a rotational spring at the
/// tip, written in SI (bare numbers) or in mm, kN, MPa, t/m^3 with units. `E` and the first
/// line's parameters are replaced by the caller.
std::string unitsCantilever(const std::string& parameters, const std::string& material,
                            const std::string& section, const std::string& spring,
                            const std::string& moment) {
  return "parameters: {" + parameters +
         "}\n"
         "materials:\n"
         "  - {name: steel, " +
         material +
         "}\n"
         "sections:\n"
         "  - {name: bar, shape: rectangle, " +
         section +
         "}\n"
         "segments:\n"
         "  - {length: L, section: bar, elements: 8}\n"
         "points:\n"
         "  - {name: tip, at: L}\n"
         "  - {name: mid, at: 0.5 * L}\n"
         "supports:\n"
         "  - {name: root, at: start, fix: clamped}\n"
         "springs:\n"
         "  - {name: s, at: tip, dof: rz, " +
         spring +
         "}\n"
         "loads:\n"
         "  - {type: point, at: tip, fy: -P, " +
         moment +
         "}\n"
         "  - {type: distributed, qy: -q}\n"
         "analyses:\n"
         "  - {type: static, name: bending}\n"
         "  - {type: modal, name: vibration, modes: 2}\n";
}

const std::string kSiTwin =
    unitsCantilever("L: 2.5, P: 1500, q: 800", "E: 210e9, nu: 0.3, rho: 7850", "b: 0.04, h: 0.06",
                    "k: 2e5", "mz: 200");
const std::string kUnitTwin =
    unitsCantilever("L: 2500 mm, P: 1.5 kN, q: 0.8 kN/m", "E: 210000 MPa, nu: 0.3, rho: 7.85 t/m^3",
                    "b: 40 mm, h: 60mm", "k: 200 kN*m/rad", "mz: 0.2 kN m");

const StaticResult& firstStatic(const RunResult& run) {
  for (const AnalysisOutcome& a : run.analyses)
    if (staticsOf(a)) return *staticsOf(a);
  throw std::logic_error("no static analysis");
}

const ModalResult& firstModal(const RunResult& run) {
  for (const AnalysisOutcome& a : run.analyses)
    if (resultOf<ModalResult>(a)) return *resultOf<ModalResult>(a);
  throw std::logic_error("no modal analysis");
}


double siOf(const std::string& text) {
  return ExpressionEvaluator().evaluate(text);
}

Dimension dimensionOfText(const std::string& text) {
  return ExpressionEvaluator().amount(text).dimension;
}

std::string unitsFailure(const ExpressionEvaluator& ev, const std::string& text) {
  try {
    ev.amount(text);
  } catch (const ExpressionError& e) {
    return e.what();
  }
  return "";
}

/// `text` with '*' before every unit written after a number, a closing parenthesis or another
/// unit, a name of the deck (in `names`) hiding the unit it is named like: the deck grammar
/// (FORMAT.md, Units), read by this test's own scan so that the reference does not borrow the
/// reader's (UnitSyntax).
std::string withUnitProducts(const std::string& text, const std::set<std::string>& names) {
  const auto isUnit = [&](const std::string& w) { return findUnit(w) && !names.count(w); };
  std::string out;
  bool afterQuantity = false;  // after a number, ')' or a unit: a unit there multiplies
  for (std::size_t i = 0; i < text.size();) {
    const unsigned char c = static_cast<unsigned char>(text[i]);
    if (std::isdigit(c) || (c == '.' && i + 1 < text.size() && std::isdigit(text[i + 1]))) {
      std::size_t end = i;
      while (end < text.size() && (std::isdigit(static_cast<unsigned char>(text[end])) ||
                                   text[end] == '.'))
        ++end;
      if (end < text.size() && (text[end] == 'e' || text[end] == 'E')) {
        std::size_t digits = end + 1;
        if (digits < text.size() && (text[digits] == '+' || text[digits] == '-')) ++digits;
        if (digits < text.size() && std::isdigit(static_cast<unsigned char>(text[digits]))) {
          end = digits;
          while (end < text.size() && std::isdigit(static_cast<unsigned char>(text[end]))) ++end;
        }
      }
      out += text.substr(i, end - i);
      afterQuantity = true;
      i = end;
    } else if (std::isalpha(c) || c == '_') {
      std::size_t end = i;
      while (end < text.size() &&
             (std::isalnum(static_cast<unsigned char>(text[end])) || text[end] == '_'))
        ++end;
      const std::string word = text.substr(i, end - i);
      const std::size_t next = text.find_first_not_of(' ', end);
      const bool call = next != std::string::npos && text[next] == '(';
      const bool unit = isUnit(word) && !call;
      if (unit && afterQuantity) out += '*';
      out += word;
      afterQuantity = unit;
      i = end;
    } else {
      if (c != ' ') afterQuantity = c == ')';
      out += text[i++];
    }
  }
  return out;
}

}  // namespace

TEST_SUITE("deck units") {
  TEST_CASE("each unit is its SI size and dimension") {
    // References: the definitions of the units (SI brochure, 9th ed., tables 2-4 and 8;
    // 1 in = 25.4 mm, 1 ft = 0.3048 m exactly). Conversions are one multiplication (and a
    // power), so they hold to one rounding: 1e-15 relative.
    const double pi = std::numbers::pi;
    struct Case {
      const char* text;
      double si;
      Dimension dimension;
    };
    const std::vector<Case> cases{
        {"6000 mm", 6, dim::length},
        {"6000mm", 6, dim::length},
        {"2 km + 30 cm + 4 um + 1 in + 1 ft", 2000.3 + 4e-6 + 0.0254 + 0.3048, dim::length},
        {"300 cm^2", 0.03, dim::area},
        {"8356 cm^4", 8356e-8, dim::secondMoment},
        {"12 t + 500 g + 2 kg", 12002.5, dim::mass},
        {"1.5 s + 20 ms", 1.52, dim::time},
        {"3 MN + 2 kN + 7 N", 3002007, dim::force},
        {"12 kN/m", 12000, dim::forcePerLength},
        {"5 kN m", 5000, dim::moment},
        {"210 GPa + 3 MPa + 4 kPa + 5 Pa + 2 bar", 210003204005, dim::pressure},
        {"7.85 t/m^3", 7850, dim::density},
        {"0.3 kg m^2", 0.3, dim::inertia},
        {"40 g*mm", 4e-5, dim::massLength},
        {"2e5 N*m/rad", 2e5, dim::rotationalStiffness},
        {"500 N*s/m", 500, dim::damping},
        {"3 N m s/rad", 3, dim::rotationalDamping},
        {"3000 rpm", 100 * pi, dim::angularSpeed},
        {"2 rev/s", 4 * pi, dim::angularSpeed},
        {"50 Hz + 1 kHz", 1050, dim::frequency},
        {"90 deg", pi / 2, dim::angle},
        {"1 rad", 1, dim::angle},
        {"9.81 m/s^2", 9.81, dim::acceleration},
        {"3 m/s", 3, dim::velocity},
        {"40 K", 40, dim::temperature},
        {"12e-6 / K", 12e-6, dim::thermalExpansion},
        {"12e-6 / K * 40 K", 12e-6 * 40, dim::none},
        {"0.3", 0.3, dim::none},
        {"3 mm / m", 0.003, dim::none},
    };
    for (const Case& c : cases) {
      CAPTURE(c.text);
      CHECK(siOf(c.text) == doctest::Approx(c.si).epsilon(1e-15));
      CHECK(dimensionOfText(c.text) == c.dimension);
    }
  }

  TEST_CASE("dimensions are carried through expressions of parameters") {
    ExpressionEvaluator ev;
    ev.define("L", ev.amount("6 m"));
    ev.define("q", ev.amount("12 kN/m"));
    ev.define("n", 4.0);  // a plain number
    // q L^2 / 8 = 12000 * 36 / 8 = 54000 N m, the simply supported span's largest moment:
    // exact in binary (integers), so compared exactly.
    const Amount M = ev.amount("q*L^2/8");
    CHECK(M.si == 54000);
    CHECK(M.dimension == dim::moment);
    CHECK(ev.amount("0.5 * L").si == 3);
    CHECK(ev.amount("n * 1.5 m + L").dimension == dim::length);
    CHECK(ev.amount("sqrt(L^2 + (8 m)^2)").si == 10);  // 6-8-10
    CHECK(ev.amount("L > 5 m ? 1 : 0").si == 1);
    CHECK(ev.dimensionOf("q") == dim::forcePerLength);
    // An angle into a function, and a plain number of radians: both readings are tried.
    CHECK(ev.evaluate("sin(30 deg)") == doctest::Approx(0.5).epsilon(1e-15));
    CHECK(ev.evaluate("sin(0.5)") == std::sin(0.5));
    CHECK(ev.amount("cos(L / (2 m))").dimension == dim::none);
    // A zero fits any field: 0 m and 0 kg are the same number.
    CHECK(ev.amount("0 kN").anyDimension);
  }

  TEST_CASE("adding different dimensions, a misspelt unit and a hidden unit are refused") {
    ExpressionEvaluator ev;
    ev.define("L", ev.amount("6 m"));
    for (const char* mixed :
         {"1 m + 1 kg", "L - 2 s", "L + 1", "L > 3 kg", "sin(L)", "exp(2 N)", "2 m - 1 m^2"}) {
      CAPTURE(mixed);
      CHECK(unitsFailure(ev, mixed).find("mixes dimensions") != std::string::npos);
    }
    CHECK(unitsFailure(ev, "6000 mmm").find("unknown unit 'mmm'; did you mean 'mm'?") !=
          std::string::npos);
    ExpressionEvaluator shadowed;
    shadowed.define("m", 2.0);  // a deck's parameter named like the metre
    CHECK(unitsFailure(shadowed, "6 m").find("not the unit") != std::string::npos);
    CHECK(shadowed.evaluate("6*m") == 12);
  }

  TEST_CASE("a deck in mm, kN and MPa gives the results of its SI twin") {
    const Study si = test::solveDeckText(kSiTwin, "si.yaml");
    const Study units = test::solveDeckText(kUnitTwin, "units.yaml");
    REQUIRE(si.run);
    REQUIRE(units.run);
    // The twins' inputs agree to one rounding of each conversion (2500 * 0.001 and 0.8 * 1000
    // are within an ulp of 2.5 and 800); the solve amplifies that by at most the measured
    // round-off bound (~1e-13 here), so 1e-12 relative is round-off, not tolerance.
    const StaticResult& a = firstStatic(*si.run);
    const StaticResult& b = firstStatic(*units.run);
    REQUIRE(a.displacement.rows() == b.displacement.rows());
    const double scale = a.displacement.cwiseAbs().maxCoeff();
    CHECK(scale > 1e-3);  // a real deflection, not zeros
    CHECK((a.displacement - b.displacement).cwiseAbs().maxCoeff() <= 1e-12 * scale);
    for (Dof d : {Dof::uy, Dof::rz}) {
      const double r = test::staticReaction(*si.run, "root", d);
      CHECK(test::staticReaction(*units.run, "root", d) == doctest::Approx(r).epsilon(1e-12));
    }
    // Closed-form cross-check of the SI run's root force: P + q L = 1500 + 800 * 2.5.
    CHECK(test::staticReaction(*si.run, "root", Dof::uy) == doctest::Approx(3500).epsilon(1e-12));
    const auto& fa = firstModal(*si.run).modes;
    const auto& fb = firstModal(*units.run).modes;
    REQUIRE(fa.size() == fb.size());
    for (std::size_t i = 0; i < fa.size(); ++i)
      CHECK(fb[i].frequencyHz == doctest::Approx(fa[i].frequencyHz).epsilon(1e-12));
    CHECK(test::deckValue(units.deck, "L") == doctest::Approx(2.5).epsilon(1e-15));
    CHECK(si.run->warnings.empty());
    for (const AnalysisOutcome& o : si.run->analyses) CHECK(o.warnings.empty());
  }

  TEST_CASE("a value of the wrong dimension names the field and both dimensions") {
    struct Case {
      std::string from, to;  // a replacement in kUnitTwin
      std::string field, message;
      int line;
    };
    const std::vector<Case> cases{
        {"E: 210000 MPa", "E: 210 mm", "materials[0].E",
         "E expects a pressure or stress (Pa), got a length (m)", 3},
        {"rho: 7.85 t/m^3", "rho: 7.85 t", "materials[0].rho",
         "rho expects a density (kg/m^3), got a mass (kg)", 3},
        {"h: 60mm", "h: 60 mm^2", "sections[0].h", "h expects a length (m), got an area (m^2)", 5},
        {"k: 200 kN*m/rad", "k: 200 kN*m", "springs[0].k",
         "k expects a rotational stiffness (N m/rad), got a moment (N m)", 14},
        {"mz: 0.2 kN m", "mz: 0.2 kN", "loads[0].mz", "mz expects a moment (N m), got a force (N)",
         16},
        {"qy: -q", "qy: -P", "loads[1].qy",
         "qy expects a force per length or a stiffness (N/m), got a force (N)", 17},
        {"at: L}", "at: 3 rad}", "points[0].at", "at expects a length (m), got an angle (rad)", 9},
    };
    for (const Case& c : cases) {
      CAPTURE(c.to);
      std::string text = kUnitTwin;
      const std::size_t at = text.find(c.from);
      REQUIRE(at != std::string::npos);
      text.replace(at, c.from.size(), c.to);
      const DeckError e = test::readingError(text, "units.yaml");
      CHECK(e.place().field == c.field);
      CHECK(e.message() == c.message);
      CHECK(e.place().line == c.line);
      CHECK(e.place().column > 1);
    }
    // A check's reference has the dimension of its quantity.
    const DeckError rpm = test::readingError(
        kUnitTwin +
            "checks:\n  - {name: f, quantity: frequency 1, reference: 3000 rpm, tolerance: 1}\n",
        "units.yaml");
    CHECK(rpm.message() ==
          "reference expects a frequency (Hz), got an angular speed (rad/s)");
  }

  TEST_CASE("the command line refuses a wrong dimension with exit 2 at file:line:col") {
    const auto dir = test::scratchDir("units_cli");
    std::string text = kUnitTwin;
    text.replace(text.find("E: 210000 MPa"), 13, "E: 210 mm");
    const auto deck = dir / "wrong.yaml";
    std::ofstream(deck) << text;
    const test::ProcessResult r = test::runBeamrotor({"check", deck.string()});
    CHECK(r.exitCode == 2);
    CHECK(r.err.find("wrong.yaml:3:") != std::string::npos);
    CHECK(r.err.find(": materials[0].E: E expects a pressure or stress (Pa), got a length (m)") !=
          std::string::npos);
    std::filesystem::remove_all(dir);
  }

  TEST_CASE("--set and --sweep take units and must match the parameter's dimension") {
    // --set L=3000mm on the deck in units equals --set L=3 on the SI twin (to round-off, as
    // above).
    StudyRequest withUnit, bare;
    withUnit.deckPath = "units.yaml";
    withUnit.sets = {"L=3000mm"};
    bare.deckPath = "si.yaml";
    bare.sets = {"L=3"};
    const Study a = solveStudyText(kUnitTwin, withUnit);
    const Study b = solveStudyText(kSiTwin, bare);
    CHECK(test::deckValue(a.deck, "L") == doctest::Approx(3).epsilon(1e-15));
    CHECK(test::staticReaction(*a.run, "root", Dof::rz) ==
          doctest::Approx(test::staticReaction(*b.run, "root", Dof::rz)).epsilon(1e-12));
    // A bare override takes the parameter's own dimension (SI).
    StudyRequest plain = withUnit;
    plain.sets = {"L=3"};
    CHECK(test::deckValue(solveStudyText(kUnitTwin, plain).deck, "L") == 3);
    // Wrong dimension.
    StudyRequest wrong = withUnit;
    wrong.sets = {"L=3 kg"};
    CHECK_THROWS_WITH_AS(solveStudyText(kUnitTwin, wrong),
                         doctest::Contains("L expects a length (m), got a mass (kg)"), DeckError);
    // A unit for a parameter the deck gives without one: its fields make it a length, and
    // 3000 mm is then exactly --set L=3 (test_deck_bare_parameters.cpp has the rest).
    StudyRequest unitForBare = bare;
    unitForBare.sets = {"L=3000 mm"};
    CHECK(test::staticReaction(*solveStudyText(kSiTwin, unitForBare).run, "root", Dof::rz) ==
          test::staticReaction(*b.run, "root", Dof::rz));
    // --sweep: values with units, converted to SI.
    const Deck deck = readDeck(parseDeckText(kUnitTwin, "units.yaml"), {});
    const DeckSweep s = parseSweepOption("L=2m:3000mm:2", deck);
    REQUIRE(s.values.size() == 3);
    CHECK(s.values[0] == 2);
    CHECK(s.values[1] == doctest::Approx(2.5).epsilon(1e-15));
    CHECK(s.values[2] == doctest::Approx(3).epsilon(1e-15));
    CHECK_THROWS_WITH_AS(parseSweepOption("L=2 s,3 s", deck),
                         doctest::Contains("L expects a length (m), got a time (s)"), DeckError);
  }

  TEST_CASE("E: 210 (meant as GPa) is warned about, in the summary and results.json") {
    std::string text = kSiTwin;
    text.replace(text.find("E: 210e9"), 8, "E: 210");
    const Study s = test::solveDeckText(text, "gpa.yaml");
    REQUIRE(s.run);
    REQUIRE(s.run->warnings.size() == 1);
    const std::string& w = s.run->warnings[0];
    CHECK(w.find("gpa.yaml:3:") == 0);
    CHECK(w.find("materials[0].E: 210 Pa is below every engineering material (1e+06 Pa, soft "
                 "elastomers)") != std::string::npos);
    CHECK(w.find("`E: 210 GPa`") != std::string::npos);
    // The deflection: P L^3/(3 E I) alone is 1500 * 2.5^3 / (3 * 210 * 7.2e-7) ~ 5e10 m, far
    // beyond the 2.5 m cantilever.
    const auto& warnings = s.run->analyses[0].warnings;
    REQUIRE(warnings.size() == 1);
    CHECK(warnings[0].find("exceeds the structure's own size (2.5 m)") != std::string::npos);

    // The plausibility bounds themselves (MaterialPlausibility.hpp): rho 7.85 (t/m^3 meant).
    std::string light = kSiTwin;
    light.replace(light.find("rho: 7850"), 9, "rho: 7.85");
    const Deck d = readDeck(parseDeckText(light, "light.yaml"), {});
    REQUIRE(d.warnings.size() == 1);
    CHECK(d.warnings[0].find("materials[0].rho: 7.85 kg/m^3 is below") != std::string::npos);
    CHECK(d.warnings[0].find("7.85 t/m^3") != std::string::npos);

    // Through the command line: a warning line and a warnings entry.
    const auto dir = test::scratchDir("units_warning");
    std::ofstream(dir / "gpa.yaml") << text;
    const test::ProcessResult r =
        test::runBeamrotor({"solve", (dir / "gpa.yaml").string(), "--out", (dir / "out").string()});
    CHECK(r.exitCode == 0);
    CHECK(r.out.find("warning: " + (dir / "gpa.yaml").string() + ":3:") != std::string::npos);
    const nlohmann::json json =
        nlohmann::json::parse(test::fileContents(dir / "out" / "results.json"));
    REQUIRE(json.contains("warnings"));
    CHECK(json["warnings"][0].get<std::string>().find("materials[0].E") != std::string::npos);
    CHECK(json["analyses"][0]["warnings"][0].get<std::string>().find("exceeds") !=
          std::string::npos);
    std::filesystem::remove_all(dir);
  }

  TEST_CASE("every shipped deck reads its parameters as plain muparser does, units by the table") {
    // The shipped decks write their parameters in engineering units (mm, kN, GPa, rpm, ...)
    // and their closed forms with them. The reference is a plain muparser (the deck functions,
    // every unit of the table a constant of its SI size, no dimensions) reading each parameter
    // and derived value one by one, the unit products written by this test's own scan; values
    // must agree exactly, bare ones (nu, counts) as well as those with units. A parameter is
    // written with a unit exactly when the reader gives it a dimension, a zero (a: 0 mm) too.
    int withUnits = 0;
    for (const auto& path : test::shippedDecks()) {
      CAPTURE(path);
      const Deck deck = readDeck(loadDeckFile(path), {});
      const YAML::Node root = YAML::LoadFile(path.string());
      mu::Parser plain;
      plain.DefineConst("pi", std::numbers::pi);
      defineSceneFunctions(plain);
      defineDeckFunctions(plain);
      for (const Unit& u : units()) plain.DefineConst(u.name, u.si);
      std::set<std::string> names;
      std::vector<std::pair<std::string, double>> expected;
      for (const char* block : {"parameters", "derived"}) {
        if (!root[block] || !root[block].IsMap()) continue;
        for (const auto& entry : root[block]) {
          const std::string name = entry.first.Scalar(), text = entry.second.Scalar();
          CAPTURE(text);
          plain.SetExpr(withUnitProducts(text, names));
          const double v = plain.Eval();
          plain.DefineConst(name, v);
          names.insert(name);
          expected.emplace_back(name, v);
          if (std::string(block) == "derived") continue;
          const bool written = withUnitProducts(text, names) != text;
          const bool dimensioned = std::any_of(deck.dimensions.begin(), deck.dimensions.end(),
                                               [&](const auto& d) { return d.first == name; });
          CHECK(written == dimensioned);
          withUnits += written;
        }
      }
      std::vector<std::pair<std::string, double>> got = deck.parameters;
      got.insert(got.end(), deck.derived.begin(), deck.derived.end());
      CHECK(got == expected);
      CHECK(deck.warnings.empty());
    }
    CHECK(withUnits > 100);  // the decks' parameters are in units, not bare SI
  }
}

TEST_SUITE("deck units") {
  TEST_CASE("a simply supported beam in kN, m and cm^4 against its closed forms") {
    // M = q L^2 / 8 and w = 5 q L^4 / (384 E I) (Euler-Bernoulli, uniform load): the Hermite
    // element is exact at its nodes for these, so the checks hold to round-off (1e-9 allows
    // the measured ~5e-13 round-off bound many times over).
    const std::string deck =
        "parameters: {L: 6 m, q: 12 kN/m, E: 210 GPa, I: 1943 cm^4}\n"
        "materials: [{name: steel, E: E, nu: 0.3, rho: 7.85 t/m^3}]\n"
        "sections: [{name: ipe, shape: general, A: 28.5 cm^2, I: I, J: 7 cm^4, kappa: 0.4,\n"
        "            depth: 200 mm}]\n"
        "segments: [{length: L, section: ipe, elements: 8}]\n"
        "points: [{name: mid, at: 0.5 * L}]\n"
        "supports: [{name: a, at: start, fix: [ux, uy]}, {name: b, at: end, fix: [uy]}]\n"
        "loads: [{type: distributed, qy: -q}]\n"
        "checks:\n"
        "  - {name: M, quantity: moment max, reference: q*L^2/8, tolerance: 1e-9}\n"
        "  - {name: w, quantity: displacement mid uy, reference: -5*q*L^4/(384*E*I),\n"
        "     tolerance: 1e-9}\n"
        "  - {name: R, quantity: reaction a uy, reference: 0.5 * q * L, tolerance: 1e-9}\n";
    const Study s = test::solveDeckText(deck, "ipe.yaml");
    CHECK(test::checkAllPass(s) == 3);
    REQUIRE(s.run);
    CHECK(s.run->checks[0].reference == 54000);  // 12000 * 36 / 8, exact in binary
  }

  TEST_CASE("a transient deck in ms and mm, and a history's time checked as a time") {
    // A 2 kg mass on an 800 N/m spring released from 10 mm: y = y0 cos(omega t), omega =
    // sqrt(k/m) = 20 rad/s. Newmark's average acceleration lags the phase by about
    // (omega dt)^2 / 12 per radian, 3.3e-5 here: at t = 0.1 s (2 rad) that is ~1.5e-4 of
    // y(0.1 s), so the tolerance is 1e-3.
    const std::string deck =
        "points: [{name: body, at: 0}]\n"
        "masses: [{at: body, m: 2 kg}]\n"
        "springs: [{at: body, dof: uy, k: 0.8 kN/m}]\n"
        "analyses:\n"
        "  - {type: transient, name: free, dt: 1 ms, end: 0.5 s,\n"
        "     initial: [{at: body, dof: uy, u: 10 mm}], record: [{name: y, at: body, dof: uy}]}\n"
        "checks:\n"
        "  - {name: y, quantity: history y at 100ms,\n"
        "     reference: 0.01 * cos(20 rad/s * 100 ms), tolerance: 1e-3}\n";  // bare: m
    const Study s = test::solveDeckText(deck, "spring.yaml");
    CHECK(test::checkAllPass(s) == 1);
    std::string wrong = deck;
    wrong.replace(wrong.find("at 100ms"), 8, "at 100mm");
    const DeckError e = test::readingError(wrong, "units.yaml");
    CHECK(e.message() == "the time expects a time (s), got a length (m)");
    CHECK(e.place().line == 8);
  }
}

TEST_SUITE("deck units") {
  TEST_CASE("odd unit syntax fails with a reason, never a crash or a wrong value") {
    ExpressionEvaluator ev;
    for (const char* odd : {"1e", "2e+", "6 mm mm mm kg^-1 s", "1e308 km", "m", "3 (mm)", "3 .mm",
                            "mm 3", "4 sin", "1 pi", "6 m(2)", "()", "2 2 m"}) {
      CAPTURE(odd);
      try {
        const Amount a = ev.amount(odd);
        CHECK(std::isfinite(a.si));
      } catch (const ExpressionError& e) {
        CHECK(std::string(e.what()).size() > 0);
      }
    }
    // The ones with a definite meaning: a product of units, and a unit alone (1 m).
    CHECK(ev.amount("6 mm mm mm kg^-1 s").dimension == Dimension::of(3, -1, 1, 0));
    CHECK(ev.amount("m").si == 1);
    CHECK(unitsFailure(ev, "1e305 km").find("largest number") != std::string::npos);
  }
}

// Load cases and combinations of frames as results: each combination against a deck carrying
// its factored loads solved on its own (a second method), the envelope's extremes against the
// extremes of every combination evaluated directly, the summary against the closed forms of a
// portal frame (slope-deflection) and of problems/continuous_beam.yaml (three-moment
// equation), and what the results directory holds for each case (JSON, VTK arrays, charts).
#include <doctest/doctest.h>
#include <vtkCellData.h>
#include <vtkNew.h>
#include <vtkPointData.h>
#include <vtkUnstructuredGrid.h>
#include <vtkXMLUnstructuredGridReader.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <regex>
#include <set>
#include <sstream>
#include <string>

#include "fem/assembly/ElementExtrema.hpp"
#include "fem/assembly/MemberExtrema.hpp"
#include "problems/cli/Summary.hpp"
#include "problems/deck/DeckReader.hpp"
#include "problems/output/JsonWriter.hpp"
#include "problems/output/Output.hpp"
#include "tests/Helpers.hpp"
#include "tests/problems/DeckTestSupport.hpp"

using namespace beamrotor;
namespace fs = std::filesystem;

// Named, not anonymous: the test sources are compiled in unity batches.
namespace frame_cases {

// The portal frame of problems/portal_frame.yaml: columns h (HEB 200), beam L (IPE 300),
// fixed bases A and D; a lateral load H at B and a gravity load w on the beam, here as two
// load cases.
constexpr double kPortalHeight = 4, kPortalSpan = 6, kPortalLateral = 10e3, kPortalGravity = 20e3, kPortalE = 210e9;
constexpr double kPortalIc = 5696e-8, kPortalAc = 78.1e-4, kPortalIb = 8356e-8, kPortalAb = 53.8e-4;

std::string portalDeck(const std::string& loads) {
  std::ostringstream d;
  d.precision(17);
  d << "model: {dimension: planar}\n"
    << "materials: [{name: steel, E: " << kPortalE << ", nu: 0.3, rho: 7850}]\n"
    << "sections:\n"
    << "  - {name: column, shape: general, A: " << kPortalAc << ", I: " << kPortalIc << ", depth: 0.2}\n"
    << "  - {name: beam, shape: general, A: " << kPortalAb << ", I: " << kPortalIb << ", depth: 0.3}\n"
    << "nodes: [{name: A, at: [0, 0]}, {name: B, at: [0, " << kPortalHeight << "]}, {name: C, at: [" << kPortalSpan
    << ", " << kPortalHeight << "]}, {name: D, at: [" << kPortalSpan << ", 0]}]\n"
    << "members:\n"
    << "  - {name: left, from: A, to: B, section: column, elements: 4}\n"
    << "  - {name: beam, from: B, to: C, section: beam, elements: 6}\n"
    << "  - {name: right, from: D, to: C, section: column, elements: 4}\n"
    << "supports: [{name: A, at: A, fix: clamped}, {name: D, at: D, fix: clamped}]\n"
    << loads << "analyses: [{type: static}]\n";
  return d.str();
}

std::string lateral(double f) {
  std::ostringstream d;
  d.precision(17);
  d << "{type: point, at: B, fx: " << f * kPortalLateral << "}";
  return d.str();
}

std::string gravity(double f) {
  std::ostringstream d;
  d.precision(17);
  d << "{type: distributed, member: beam, qy: " << -f * kPortalGravity << "}";
  return d.str();
}

const std::string kPortalCases = "loads: []\n"
                                 "load_cases:\n"
                                 "  - {name: lateral, loads: [" + lateral(1) + "]}\n"
                                 "  - {name: gravity, loads: [" + gravity(1) + "]}\n"
                                 "combinations:\n"
                                 "  - {name: both, factors: {lateral: 1, gravity: 1}}\n"
                                 "  - {name: ULS, factors: {lateral: 1.5, gravity: 1.35}}\n"
                                 "  - {name: wind, factors: {lateral: -1.5, gravity: 1}}\n";

const CaseOutcome& caseNamed(const RunResult& run, const std::string& name) {
  const auto& cases = casesOf(run.analyses.front());
  const auto it = std::find_if(cases.begin(), cases.end(),
                               [&](const CaseOutcome& c) { return c.name == name; });
  REQUIRE(it != cases.end());
  return *it;
}

/// The numbers of a summary line after `key` (e.g. "Mz "), in order.
std::vector<double> numbersAfter(const std::string& line, const std::string& key) {
  std::vector<double> out;
  for (std::size_t at = line.find(key); at != std::string::npos; at = line.find(key, at + 1))
    out.push_back(std::stod(line.substr(at + key.size())));
  return out;
}

/// The first line of `text` at or after `from` that contains `what`.
std::string lineWith(const std::string& text, const std::string& what, std::size_t from = 0) {
  const std::size_t at = text.find(what, from);
  REQUIRE(at != std::string::npos);
  const std::size_t start = text.rfind('\n', at) + 1;
  return text.substr(start, text.find('\n', at) - start);
}

// Slope-deflection closed forms of the portal (members inextensible): the sway, the base
// moments of the lateral load and the corner moment of the gravity load; the deck's own
// references (problems/portal_frame.yaml's header).
struct PortalClosedForm {
  double a = kPortalE * kPortalIc / kPortalHeight, b = kPortalE * kPortalIb / kPortalSpan, k = b / a;
  double Delta = kPortalLateral * kPortalHeight * kPortalHeight * (4 * a + 6 * b) / (24 * a * (a + 6 * b));
  double theta = 6 * a * Delta / (kPortalHeight * (4 * a + 6 * b));
  double Mlat = 2 * a * (3 * Delta / kPortalHeight - theta);
  double MB = kPortalGravity * kPortalSpan * kPortalSpan / (6 * (2 + k));
  double Vlat = (kPortalLateral * kPortalHeight - 2 * Mlat) / kPortalSpan;
};

}  // namespace frame_cases

using namespace frame_cases;

TEST_SUITE("load cases") {
  // Superposition and the direct solve agree to round-off (the solutions' measured round-off
  // is about 1e-14 here); 1e-9 as the decks' own checks allow.
  constexpr double kExact = 1e-9;

  TEST_CASE("a frame's combination equals its factored loads solved directly, extremes too") {
    const Study s = test::solveDeckText(portalDeck(kPortalCases), "portal_cases.yaml");
    const RunResult& run = *s.run;
    const Model& model = *run.model;
    const Study d = test::solveDeckText(
        portalDeck("loads: [" + lateral(1.5) + ", " + gravity(1.35) + "]\n"), "portal_uls.yaml");
    const RunResult& direct = *d.run;
    const CaseOutcome& uls = caseNamed(run, "ULS");
    const StaticResult& r = *staticsOf(direct.analyses.front());
    // The factored sum of the cases, component by component.
    const StaticResult &l = caseNamed(run, "lateral").statics, &g = caseNamed(run, "gravity").statics;
    for (std::size_t i = 0; i < uls.statics.reactions.size(); ++i)
      CHECK(uls.statics.reactions[i].value ==
            doctest::Approx(1.5 * l.reactions[i].value + 1.35 * g.reactions[i].value)
                .epsilon(kExact)
                .scale(kPortalLateral * kPortalHeight));
    for (const char* support : {"A", "D"})
      for (Dof dof : {Dof::ux, Dof::uy, Dof::rz})
        CHECK(uls.statics.reaction(support, dof) ==
              doctest::Approx(r.reaction(support, dof)).epsilon(kExact).scale(kPortalLateral * kPortalHeight));
    const double scale = r.displacement.cwiseAbs().maxCoeff();
    CHECK((uls.statics.displacement - r.displacement).cwiseAbs().maxCoeff() <= kExact * scale);
    // Along the members, under the combination's own span loads: every resultant's extremes,
    // the deflection from the chord and the largest displacement and stress.
    const LoadedSolution combined = uls.on(model), alone{*direct.model, r.displacement};
    for (const auto& [name, elements] : model.members()) {
      CAPTURE(name);
      const auto a = memberForceRanges(combined, elements), b = memberForceRanges(alone, elements);
      for (std::size_t c = 0; c < 6; ++c) {
        CHECK(a[c].max.value == doctest::Approx(b[c].max.value).epsilon(kExact).scale(kPortalGravity * kPortalSpan * kPortalSpan));
        CHECK(a[c].min.value == doctest::Approx(b[c].min.value).epsilon(kExact).scale(kPortalGravity * kPortalSpan * kPortalSpan));
      }
      CHECK(largestChordDeflection(combined, elements).value ==
            doctest::Approx(largestChordDeflection(alone, elements).value).epsilon(kExact));
    }
    CHECK(largestDisplacement(combined).value ==
          doctest::Approx(largestDisplacement(alone).value).epsilon(kExact));
    const auto stress = [](const LoadedSolution& x) {
      return largestPeak(elementPeaks(x), &ElementPeaks::stress)->value;
    };
    CHECK(stress(combined) == doctest::Approx(stress(alone)).epsilon(kExact));
    // The case's own loads are on the one model: its elements carry none of them.
    CHECK(model.loads().empty());
  }

  TEST_CASE("a frame's envelope: every extreme that of a combination evaluated directly") {
    const Study s = test::solveDeckText(portalDeck(kPortalCases), "portal_cases.yaml");
    const RunResult& run = *s.run;
    const Model& model = *run.model;
    const Json doc = runJson(run);
    const Json& env = doc["analyses"][0]["envelope"];
    const auto& cases = casesOf(run.analyses.front());
    for (const auto& [name, elements] : model.members())
      for (std::size_t c = 0; c < 6; ++c) {
        const std::string component = componentName(kForceComponents[c]);
        CAPTURE(name);
        CAPTURE(component);
        double hi = -1e300, lo = 1e300;
        std::string hiBy, loBy;
        for (const CaseOutcome& k : cases) {
          if (!k.combination) continue;
          const ComponentRange r = memberForceRanges(k.on(model), elements)[c];
          if (r.max.value > hi) hi = r.max.value, hiBy = k.name;
          if (r.min.value < lo) lo = r.min.value, loBy = k.name;
        }
        const Json& e = env["members"][name][component];
        CHECK(e["max"]["value"].get<double>() == hi);
        CHECK(e["min"]["value"].get<double>() == lo);
        if (std::abs(hi) > 1e-6 * kPortalGravity * kPortalSpan * kPortalSpan) CHECK(e["max"]["case"] == hiBy);
        if (std::abs(lo) > 1e-6 * kPortalGravity * kPortalSpan * kPortalSpan) CHECK(e["min"]["case"] == loBy);
      }
    double largest = 0, stress = 0;
    std::string largestBy, stressBy;
    for (const CaseOutcome& k : cases) {
      if (!k.combination) continue;
      const double u = largestDisplacement(k.on(model)).value;
      const double sigma = largestPeak(elementPeaks(k.on(model)), &ElementPeaks::stress)->value;
      if (u > largest) largest = u, largestBy = k.name;
      if (sigma > stress) stress = sigma, stressBy = k.name;
    }
    CHECK(env["max_displacement"]["value"].get<double>() == largest);
    CHECK(env["max_displacement"]["case"] == largestBy);
    CHECK(env["max_stress"]["value"].get<double>() == stress);
    CHECK(env["max_stress"]["case"] == stressBy);
    // Each case carries its stresses, factors and warnings, as the analysis does.
    for (const Json& c : doc["analyses"][0]["cases"]) {
      CHECK(c.contains("max_stress"));
      CHECK(c.contains("max_shear"));
      CHECK(c["warnings"].is_array());
      CHECK(c.contains("members"));
    }
    CHECK(doc["analyses"][0]["cases"][3]["factors"]["lateral"] == 1.5);
    CHECK(doc["analyses"][0]["loaded"] == false);
  }

  TEST_CASE("a portal frame's summary: its combination against the slope-deflection forms") {
    const Study s = test::solveDeckText(portalDeck(kPortalCases), "portal_cases.yaml");
    std::ostringstream summary;
    cli::printRunResults(summary, s.deck, *s.run);
    const std::string text = summary.str();
    // The unloaded solution of the empty loads: is not printed; every case is.
    CHECK(text.find("its `loads:` is empty") != std::string::npos);
    CHECK(text.find("reactions") > text.find("load cases and combinations"));
    const std::size_t both = text.find("combination 'both' = 1 lateral + 1 gravity:");
    REQUIRE(both != std::string::npos);
    CHECK(text.find("combination 'ULS' = 1.5 lateral + 1.35 gravity:") != std::string::npos);
    // 'both' is the portal of problems/portal_frame.yaml. The closed forms neglect the
    // members' axial strain (up to 1.9 %: that deck's header): 2.5e-2, as its checks allow;
    // the vertical reaction follows from statics and is nearly exact.
    const PortalClosedForm f;
    const auto reaction = [&](const std::string& support, const std::string& key) {
      return numbersAfter(lineWith(text, "      " + support + "  ", both), key).at(0);
    };
    CHECK(test::relError(reaction("A", "mz "), f.Mlat - f.MB / 2) < 2.5e-2);
    CHECK(test::relError(reaction("D", "mz "), f.Mlat + f.MB / 2) < 2.5e-2);
    CHECK(test::relError(reaction("A", "fx "), -kPortalLateral / 2 + 1.5 * f.MB / kPortalHeight) < 2.5e-2);
    CHECK(test::relError(reaction("D", "fy "), kPortalGravity * kPortalSpan / 2 + f.Vlat) < 1e-3);
    // The sway at B, the largest displacement of a beam pushed sideways... and sagging.
    const std::string points = lineWith(text, "      B           at (0, 4) m", both);
    CHECK(test::relError(numbersAfter(points, "ux ").at(0), f.Delta) < 2.5e-2);
    // The envelope: the lateral load reversed ("wind") governs the smallest base moment at D.
    const std::string envelope = lineWith(text, "      D           ", text.find("envelope over"));
    CHECK(envelope.find("mz ") != std::string::npos);
    CHECK(envelope.find("[wind]") != std::string::npos);
  }

  TEST_CASE("continuous_beam.yaml's summary against the three-moment equation") {
    const test::SolvedDeck solved =
        test::solveShippedDeckToScratch("continuous_beam.yaml", "cb_summary");
    const std::string& text = solved.process.out;
    const Deck deck = readDeck(loadDeckFile(test::problemsDir() / "continuous_beam.yaml"), {});
    const double L = test::deckValue(deck, "L"), gk = test::deckValue(deck, "gk"),
                 qk = test::deckValue(deck, "qk");
    // Two equal spans under p1 and p2 (the deck's header): M_B = -(p1 + p2) L^2 / 16,
    // R_A = p1 L / 2 + M_B / L, the largest span moment R_A^2 / (2 p1), R_B = (p1 + p2) L / 2
    // - 2 M_B / L. The summary prints 6 significant digits: 5e-6 relative at worst.
    const auto MB = [&](double p1, double p2) { return -(p1 + p2) * L * L / 16; };
    const auto span = [&](double p1, double p2) {
      const double RA = p1 * L / 2 + MB(p1, p2) / L;
      return RA * RA / (2 * p1);
    };
    const double pu = 1.35 * gk + 1.5 * qk, pd = 1.35 * gk;
    constexpr double kPrinted = 5e-6;
    CHECK(text.find("its `loads:` is empty") != std::string::npos);
    // ULS_both: the support moment at B, the end of span 1.
    const std::size_t uls = text.find("combination 'ULS_both'");
    REQUIRE(uls != std::string::npos);
    const std::string span1 = lineWith(text, "span1       N ", uls);
    CHECK(test::relError(numbersAfter(span1, "Mz ").at(0), MB(pu, pu)) < kPrinted);
    // The envelope: span 1's largest moment from ULS_span1, its smallest from ULS_both, and
    // B's largest reaction from ULS_both.
    const std::size_t env = text.find("envelope over the combinations");
    REQUIRE(env != std::string::npos);
    const std::string member = lineWith(text, "span1:", env);
    const std::vector<double> mz = numbersAfter(member, "Mz ");
    REQUIRE(mz.size() == 1);
    CHECK(test::relError(mz[0], span(pu, pd)) < kPrinted);
    CHECK(member.find("[ULS_span1] / ") != std::string::npos);
    const double smallest = std::stod(member.substr(member.rfind("/ ") + 2));
    CHECK(test::relError(smallest, MB(pu, pu)) < kPrinted);
    const std::string b = lineWith(text, "      B           fy ", env);
    CHECK(test::relError(numbersAfter(b, "fy ").at(0), (pu + pu) * L / 2 - 2 * MB(pu, pu) / L) <
          kPrinted);
    CHECK(b.find("[ULS_both]") != std::string::npos);
    // No load pulls along the beam: its axial reaction is 0 in every combination, which names
    // no governing combination.
    CHECK(lineWith(text, "      A           fx ", env).find("fx 0 / 0 ") != std::string::npos);
    // The charts of the combinations that govern (the largest displacement, the largest
    // stress and the extreme moments) and the envelope drawn on the frame; no empty main chart.
    CHECK(fs::exists(solved.dir / "static_frame_envelope.png"));
    CHECK_FALSE(fs::exists(solved.dir / "static_frame.png"));
    CHECK(fs::exists(solved.dir / "static_frame_case_04.png"));  // ULS_both
    CHECK(fs::exists(solved.dir / "static_frame_case_05.png"));  // ULS_span1
    fs::remove_all(solved.dir.parent_path());
  }

  TEST_CASE("each case's VTK file carries the analysis' own arrays") {
    const Study s = test::solveDeckText(portalDeck(kPortalCases), "portal_cases.yaml");
    const fs::path dir = test::scratchDir("portal_case_vtk") / "out";
    OutputChoices choices;
    choices.allCases = true;  // every case's file, not only the governing combinations'
    choices.charts = ChartFormat::none;
    writeRunOutputs(*s.run, dir, choices);
    const auto arrays = [](const fs::path& file) {
      vtkNew<vtkXMLUnstructuredGridReader> reader;
      reader->SetFileName(file.string().c_str());
      reader->Update();
      std::set<std::string> names;
      for (vtkDataSetAttributes* data : {static_cast<vtkDataSetAttributes*>(
                                             reader->GetOutput()->GetPointData()),
                                         static_cast<vtkDataSetAttributes*>(
                                             reader->GetOutput()->GetCellData())})
        for (int i = 0; i < data->GetNumberOfArrays(); ++i) names.insert(data->GetArrayName(i));
      return names;
    };
    const std::set<std::string> own = arrays(dir / "static.vtu");
    CHECK(own.count("stress"));
    for (int k = 1; k <= 5; ++k) {
      char name[32];
      std::snprintf(name, sizeof name, "static_case_%02d.vtu", k);
      CAPTURE(name);
      CHECK(arrays(dir / name) == own);
    }
    fs::remove_all(dir.parent_path());
  }

  TEST_CASE("many combinations: one summary line each, member extremes through the envelope") {
    // 30 spans and 700 combinations: 30 x 701 member entries pass kCaseMemberEntries.
    std::ostringstream d;
    d << "model: {dimension: planar}\n"
      << "materials: [{name: steel, E: 210e9, nu: 0.3}]\n"
      << "sections: [{name: ipe, shape: general, A: 53.8e-4, I: 8356e-8, depth: 0.3}]\n"
      << "nodes:\n";
    for (int i = 0; i <= 30; ++i) d << "  - {name: J" << i << ", at: [" << 4 * i << ", 0]}\n";
    d << "members:\n";
    for (int i = 0; i < 30; ++i)
      d << "  - {name: m" << i << ", from: J" << i << ", to: J" << i + 1 << ", section: ipe, elements: 1}\n";
    d << "supports:\n  - {name: S0, at: J0, fix: pinned}\n";
    for (int i = 1; i <= 30; ++i) d << "  - {name: S" << i << ", at: J" << i << ", fix: [uy]}\n";
    d << "loads: []\nload_cases: [{name: q, loads: [{type: distributed, qy: -1e4}]}]\n"
      << "combinations:\n";
    for (int k = 1; k <= 700; ++k) d << "  - {name: k" << k << ", factors: {q: " << k << "}}\n";
    d << "analyses: [{type: static}]\n";
    const Study s = test::solveDeckText(d.str(), "many.yaml");
    const RunResult& run = *s.run;
    const Json doc = runJson(run);
    const Json& analysis = doc["analyses"][0];
    CHECK_FALSE(analysis["cases"][0].contains("members"));
    CHECK(analysis["cases"][0].contains("max_stress"));
    // The largest factor governs every extreme: its moments are k times the case's (a linear
    // model), the envelope's those of k700 evaluated directly.
    const CaseOutcome& top = caseNamed(run, "k700");
    const auto& members = run.model->members();
    for (std::size_t m = 0; m < members.size(); m += 7) {
      const ComponentRange r = memberForceRanges(top.on(*run.model), members[m].second)[5];
      const Json& e = analysis["envelope"]["members"][members[m].first]["Mz"];
      CHECK(e["max"]["value"].get<double>() == r.max.value);
      CHECK(e["min"]["value"].get<double>() == r.min.value);
      CHECK(e["min"]["case"] == "k700");
    }
    std::ostringstream summary;
    cli::printRunResults(summary, s.deck, run);
    const std::string text = summary.str();
    CHECK(text.find("    combination 'k350' = 350 q") != std::string::npos);
    CHECK(text.find("combination 'k350' = 350 q:") == std::string::npos);  // no full block
    CHECK(text.find("the 20 of the largest bending moment among 30") != std::string::npos);
  }

  TEST_CASE("machine_platform.yaml's summary: round-off shown as 0, the closed forms kept") {
    const test::SolvedDeck solved =
        test::solveShippedDeckToScratch("machine_platform.yaml", "platform_summary");
    const std::string& text = solved.process.out;
    const Deck deck = readDeck(loadDeckFile(test::problemsDir() / "machine_platform.yaml"), {});
    const double F = test::deckValue(deck, "F"), h = test::deckValue(deck, "h");
    // The belt pulls the platform along x: four equal columns, each clamped at both ends
    // (the floor does not turn), carry F/4 and the moment F/4 h/2 at each end. Out of plane
    // (z, mx, my) the frame is symmetric and unloaded: those components vanish exactly, and
    // the solve leaves them as round-off of 1e-15 N beside 5000 N.
    const std::size_t belt = text.find("case 'belt':");
    REQUIRE(belt != std::string::npos);
    const std::string a1 = lineWith(text, "        A1          fx ", belt);
    CHECK(numbersAfter(a1, "fx ").at(0) == doctest::Approx(-F / 4).epsilon(5e-6));
    CHECK(numbersAfter(a1, "mz ").at(0) == doctest::Approx(F / 4 * h / 2).epsilon(5e-6));
    // Printed as a bare 0 (formatValue prints exact zero as "0"), not as 1.27145e-15.
    CHECK(a1.find("fz 0 N ") != std::string::npos);
    CHECK(a1.find("mx 0 N m ") != std::string::npos);
    CHECK(a1.find("my 0 N m ") != std::string::npos);
    const std::string b0 = lineWith(text, "        B0          at ", belt);
    CHECK(b0.find("uz 0 m ") != std::string::npos);
    CHECK(b0.find("ry 0 rad ") != std::string::npos);
    CHECK(numbersAfter(b0, "ux ").at(0) > 0);
    // A member resultant that is round-off all along has no place: "Vz 0", not "Vz 1e-15 @ 1.5".
    const std::string c0 = lineWith(text, "        c0          N ", belt);
    CHECK(c0.find("Vz 0 ") != std::string::npos);
    CHECK(c0.find("Vz 0 @") == std::string::npos);
    CHECK(numbersAfter(c0, "Vy ").at(0) == doctest::Approx(-F / 4).epsilon(5e-6));
    // The startup case twists the platform: every column bends about both axes, and its small
    // but real out-of-plane values stay.
    const std::size_t startup = text.find("case 'startup':");
    REQUIRE(startup != std::string::npos);
    const std::string a0 = lineWith(text, "        A0          fx ", startup);
    CHECK(numbersAfter(a0, "fz ").at(0) != 0);
    CHECK(numbersAfter(a0, "my ").at(0) != 0);
    fs::remove_all(solved.dir.parent_path());
  }

  TEST_CASE("braced_panel.yaml's summary: the pin-jointed panel's shear is 0, not round-off") {
    const test::SolvedDeck solved =
        test::solveShippedDeckToScratch("braced_panel.yaml", "braced_summary");
    const std::string& text = solved.process.out;
    // The stretched rod A-D carries the deck's 12.5 kN brace force on A = 3.14 cm^2 (its
    // check); nothing in the pin-jointed panel bends, so no section carries shear: the solve
    // leaves 5.8e-17 MPa of it, shown as 0 and without a place.
    const std::string normal = lineWith(text, "  largest normal stress ");
    CHECK(numbersAfter(normal, "stress ").at(0) == doctest::Approx(12500 / 3.14e-4 * 1e-6).epsilon(5e-6));
    CHECK(lineWith(text, "  largest shear stress ") == "  largest shear stress  0 MPa");
    fs::remove_all(solved.dir.parent_path());
  }
}

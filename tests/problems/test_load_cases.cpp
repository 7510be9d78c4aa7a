// Load cases and combinations (load_cases:, combinations:): a two-span continuous beam under
// pattern loading against the standard closed forms for two equal spans under a uniform load
// (three-moment equation), a combination against the factored sum of its cases solved as
// separate decks, the envelope in results.json against the extremes over the combinations,
// and a check reading a case.
#include <doctest/doctest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <set>
#include <nlohmann/json.hpp>
#include <vtkDataArray.h>
#include <vtkNew.h>
#include <vtkPointData.h>
#include <vtkUnstructuredGrid.h>
#include <vtkXMLUnstructuredGridReader.h>
#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>

#include "fem/assembly/ElementExtrema.hpp"
#include "fem/assembly/MemberEnvelope.hpp"
#include "fem/assembly/MemberExtrema.hpp"
#include "fem/model/LineElement.hpp"
#include "fem/assembly/Recovery.hpp"
#include "fem/static/Static.hpp"
#include "problems/deck/parse/DeckError.hpp"
#include "problems/deck/DeckReader.hpp"
#include "problems/deck/parse/DeckSource.hpp"
#include "problems/output/files/CsvTable.hpp"
#include "problems/output/JsonWriter.hpp"
#include "problems/output/Output.hpp"
#include "problems/run/Study.hpp"
#include "tests/problems/DeckTestSupport.hpp"

using namespace beamrotor;

namespace {

// Two equal spans L under q (N/m), EI constant: with both spans loaded the middle support
// carries M = -q L^2 / 8 and the reactions are 3qL/8, 10qL/8, 3qL/8; with one span loaded
// M = -q L^2 / 16, the reactions 7qL/16, 10qL/16, -qL/16 and the loaded span's largest
// moment is (7qL/16)^2 / (2q) = 49 q L^2 / 512.
constexpr double kL = 5, kQ = 12e3;

/// The frame deck of the two spans, pinned at A, B and C; `loads` is the deck's loads part.
std::string twoSpanDeck(const std::string& loads) {
  std::ostringstream d;
  d.precision(17);
  d << "model: {dimension: planar}\n"
    << "materials: [{name: steel, E: 210e9, nu: 0.3}]\n"
    << "sections: [{name: beam, shape: general, A: 53.8e-4, I: 8356e-8, J: 1e-6, depth: 0.3, "
       "width: 0.15}]\n"
    << "nodes: [{name: A, at: [0, 0]}, {name: B, at: [" << kL << ", 0]}, {name: C, at: ["
    << 2 * kL << ", 0]}]\n"
    << "members:\n"
    << "  - {name: span1, from: A, to: B, section: beam, elements: 4}\n"
    << "  - {name: span2, from: B, to: C, section: beam, elements: 4}\n"
    << "supports:\n"
    << "  - {name: A, at: A, fix: pinned}\n"
    << "  - {name: B, at: B, fix: [uy]}\n"
    << "  - {name: C, at: C, fix: [uy]}\n"
    << loads << "analyses: [{type: static}]\n";
  return d.str();
}

std::string spanLoad(const std::string& member, double q) {
  std::ostringstream d;
  d.precision(17);
  d << "{type: distributed, member: " << member << ", qy: " << -q << "}";
  return d.str();
}

const std::string kCases = "load_cases:\n"
                           "  - {name: one, loads: [" + spanLoad("span1", kQ) + "]}\n"
                           "  - {name: two, loads: [" + spanLoad("span2", kQ) + "]}\n"
                           "combinations:\n"
                           "  - {name: both, factors: {one: 1, two: 1}}\n"
                           "  - {name: ULS, factors: {one: 1.35, two: 1.5}}\n"
                           "  - {name: left, factors: {one: 1.5}}\n";

const RunResult& onlyRun(const Study& s) {
  const auto runs = test::runsOf(s);
  REQUIRE(runs.size() == 1);
  return *runs.front();
}

const CaseOutcome& caseOf(const RunResult& run, const std::string& name) {
  const auto& cases = casesOf(run.analyses.front());
  const auto it = std::find_if(cases.begin(), cases.end(),
                               [&](const CaseOutcome& c) { return c.name == name; });
  REQUIRE(it != cases.end());
  return *it;
}

double memberMaxAbsMz(const LoadedSolution& solution, const std::string& member) {
  for (const auto& [name, elements] : solution.model->members())
    if (name == member) {
      const auto ranges = memberForceRanges(solution, elements);
      const ComponentRange& r = ranges[5];  // Mz
      return std::max(std::abs(r.max.value), std::abs(r.min.value));
    }
  FAIL("no member " << member);
  return 0;
}


/// A malformed load_cases:/combinations: part, the line (the deck's loads part starts on line
/// 12; a block's own place is where its value starts), the field and a phrase the message must contain.
struct BadCases {
  std::string text;
  int line;
  std::string field, phrase;
};

}  // namespace

TEST_SUITE("load cases") {
  // Euler-Bernoulli elements under a uniform load with consistent nodal loads are exact at
  // the nodes and the recovered moments exact between them, so what remains is round-off:
  // the run's measured round-off is about 1e-13 here, 1e-9 leaves margin for other platforms.
  constexpr double kExact = 1e-9;

  TEST_CASE("two-span beam under pattern loading matches the closed forms") {
    const Study s = test::solveDeckText(twoSpanDeck(kCases), "two_span.yaml");
    const RunResult& run = onlyRun(s);
    REQUIRE(casesOf(run.analyses.front()).size() == 5);
    const double qL = kQ * kL, qL2 = kQ * kL * kL;

    const CaseOutcome& both = caseOf(run, "both");
    CHECK(both.combination);
    CHECK(both.statics.reaction("B", Dof::uy) == doctest::Approx(10 * qL / 8).epsilon(kExact));
    CHECK(both.statics.reaction("A", Dof::uy) == doctest::Approx(3 * qL / 8).epsilon(kExact));
    // The support moment qL^2/8 is the largest |Mz| of either span (the span moments are
    // 9qL^2/128).
    CHECK(memberMaxAbsMz(both.on(*run.model), "span1") == doctest::Approx(qL2 / 8).epsilon(kExact));
    CHECK(memberMaxAbsMz(both.on(*run.model), "span2") == doctest::Approx(qL2 / 8).epsilon(kExact));

    const CaseOutcome& one = caseOf(run, "one");
    CHECK_FALSE(one.combination);
    CHECK(one.statics.reaction("A", Dof::uy) == doctest::Approx(7 * qL / 16).epsilon(kExact));
    CHECK(one.statics.reaction("B", Dof::uy) == doctest::Approx(10 * qL / 16).epsilon(kExact));
    CHECK(one.statics.reaction("C", Dof::uy) == doctest::Approx(-qL / 16).epsilon(kExact));
    CHECK(memberMaxAbsMz(one.on(*run.model), "span1") == doctest::Approx(49 * qL2 / 512).epsilon(kExact));
    // The unloaded span carries the support moment qL^2/16, falling linearly to C.
    CHECK(memberMaxAbsMz(one.on(*run.model), "span2") == doctest::Approx(qL2 / 16).epsilon(kExact));
  }

  TEST_CASE("a combination equals the factored sum of its cases solved as separate decks") {
    const Study s = test::solveDeckText(twoSpanDeck(kCases), "two_span.yaml");
    const RunResult& run = onlyRun(s);
    const Study s1 = test::solveDeckText(twoSpanDeck("loads: [" + spanLoad("span1", kQ) + "]\n"),
                                         "one.yaml");
    const Study s2 = test::solveDeckText(twoSpanDeck("loads: [" + spanLoad("span2", kQ) + "]\n"),
                                         "two.yaml");
    const StaticResult& r1 = *staticsOf(onlyRun(s1).analyses.front());
    const StaticResult& r2 = *staticsOf(onlyRun(s2).analyses.front());
    const CaseOutcome& uls = caseOf(run, "ULS");
    const NodalField sum = 1.35 * r1.displacement + 1.5 * r2.displacement;
    const double du = (uls.statics.displacement - sum).cwiseAbs().maxCoeff();
    const double scale = sum.cwiseAbs().maxCoeff();
    MESSAGE("ULS displacement vs factored sum, max relative difference " << du / scale);
    CHECK(du <= kExact * scale);
    for (const char* support : {"A", "B", "C"}) {
      const double expected = 1.35 * r1.reaction(support, Dof::uy) + 1.5 * r2.reaction(support, Dof::uy);
      CHECK(uls.statics.reaction(support, Dof::uy) ==
            doctest::Approx(expected).epsilon(kExact).scale(kQ * kL));
    }
    // Member forces of the combination (under its cases' span loads, factored) match those of
    // one deck carrying the factored loads.
    const Study sf = test::solveDeckText(
        twoSpanDeck("loads: [" + spanLoad("span1", 1.35 * kQ) + ", " + spanLoad("span2", 1.5 * kQ) +
                    "]\n"),
        "factored.yaml");
    const RunResult& f = onlyRun(sf);
    const LoadedSolution direct{*f.model, staticsOf(f.analyses.front())->displacement};
    for (const char* member : {"span1", "span2"})
      CHECK(memberMaxAbsMz(uls.on(*run.model), member) ==
            doctest::Approx(memberMaxAbsMz(direct, member)).epsilon(kExact));
  }

  TEST_CASE("the envelope in results.json is the extreme over the combinations") {
    const Study s = test::solveDeckText(twoSpanDeck(kCases), "two_span.yaml");
    const RunResult& run = onlyRun(s);
    const Json doc =
        runJson(run);
    const Json& analysis = doc["analyses"][0];
    REQUIRE(analysis.contains("envelope"));
    REQUIRE(analysis["cases"].size() == 5);
    const Json& env = analysis["envelope"];
    for (const char* support : {"A", "B", "C"}) {
      double hi = -1e300, lo = 1e300;
      for (const CaseOutcome& c : casesOf(run.analyses.front())) {
        if (!c.combination) continue;
        hi = std::max(hi, c.statics.reaction(support, Dof::uy));
        lo = std::min(lo, c.statics.reaction(support, Dof::uy));
      }
      CHECK(env["reactions"][support]["fy"]["max"]["value"].get<double>() == hi);
      CHECK(env["reactions"][support]["fy"]["min"]["value"].get<double>() == lo);
    }
    // C's reaction: largest with both spans at their ULS factors, smallest (negative) with the
    // first span alone.
    CHECK(env["reactions"]["C"]["fy"]["max"]["case"] == "ULS");
    CHECK(env["reactions"]["C"]["fy"]["min"]["case"] == "left");
    for (const char* member : {"span1", "span2"}) {
      double hi = -1e300, lo = 1e300;
      for (const CaseOutcome& c : casesOf(run.analyses.front())) {
        if (!c.combination) continue;
        for (const auto& [name, elements] : run.model->members())
          if (name == member) {
            const auto r = memberForceRanges(c.on(*run.model), elements)[5];
            hi = std::max(hi, r.max.value);
            lo = std::min(lo, r.min.value);
          }
      }
      CHECK(env["members"][member]["Mz"]["max"]["value"].get<double>() == hi);
      CHECK(env["members"][member]["Mz"]["min"]["value"].get<double>() == lo);
    }
  }

  TEST_CASE("a check names a case or a combination") {
    const double qL = kQ * kL;
    std::ostringstream checks;
    checks.precision(17);
    checks << "checks:\n"
           << "  - {name: R_C one, quantity: reaction C uy, case: one, reference: " << -qL / 16
           << ", tolerance: 1e-9}\n"
           << "  - {name: R_B both, quantity: reaction B uy, case: both, reference: "
           << 10 * qL / 8 << ", tolerance: 1e-9}\n";
    const Study s = test::solveDeckText(twoSpanDeck(kCases) + checks.str(), "two_span.yaml");
    CHECK(test::checkAllPass(s) == 2);
    CHECK_THROWS_AS(test::solveDeckText(twoSpanDeck(kCases) +
                                            "checks: [{name: x, quantity: reaction C uy, case: "
                                            "nope, reference: 1, tolerance: 1}]\n",
                                        "bad.yaml"),
                    DeckError);
  }

  TEST_CASE("malformed load cases and combinations name file, line and field") {
    const std::string one = "  - {name: one, loads: [" + spanLoad("span1", kQ) + "]}\n";
    const std::vector<BadCases> cases{
        {"load_cases:\n" + one + one, 14, "load_cases[1].name",
         "already a load case or combination named 'one'"},
        {"load_cases:\n" + one + "combinations:\n  - {name: one, factors: {one: 2}}\n", 15,
         "combinations[0].name", "already a load case or combination named 'one'"},
        {"load_cases:\n" + one + "combinations:\n  - {name: c, factors: {two: 2}}\n", 15,
         "combinations[0].factors.two", "no load case 'two'"},
        {"load_cases:\n" + one + "combinations:\n  - {name: c, factors: {}}\n", 15,
         "combinations[0].factors", "at least one factor"},
        {"load_cases:\n" + one + "combinations:\n  - {name: c, factor: {one: 1}}\n", 15,
         "combinations[0].factor", "unknown key"},
        {"combinations:\n  - {name: c, factors: {one: 1}}\n", 13, "combinations",
         "define them under load_cases"},
        {"load_cases:\n  - {name: one, loads: {type: point}}\n", 13, "load_cases[0].loads",
         "expected a list of loads"},
        {"load_cases:\n  - {name: one}\n", 13, "load_cases[0].loads", "loads"},
        {"load_cases:\n  - {name: one, loads: [{type: distributed, member: span9, qy: 1}]}\n", 13,
         "load_cases[0].loads[0].member", "span9"},
        {"load_cases:\n" + one + "combinations:\n  - {name: c, factors: {one: abc}}\n", 15,
         "combinations[0].factors.one", "abc"},
    };
    for (const BadCases& c : cases) {
      CAPTURE(c.text);
      const DeckError e = test::readingError(twoSpanDeck(c.text), "cases.yaml");
      CHECK(e.file() == "cases.yaml");
      CHECK(e.place().line == c.line);
      CHECK(e.place().field == c.field);
      CHECK(e.message().find(c.phrase) != std::string::npos);
    }
  }

  TEST_CASE("each case, solved with the shared factor, equals its loads solved alone") {
    const Study s = test::solveDeckText(twoSpanDeck(kCases), "two_span.yaml");
    const RunResult& run = onlyRun(s);
    const Study alone = test::solveDeckText(
        twoSpanDeck("loads: [" + spanLoad("span2", kQ) + "]\n"), "two.yaml");
    const StaticResult& direct = *staticsOf(onlyRun(alone).analyses.front());
    const CaseOutcome& two = caseOf(run, "two");
    // Same matrix, same right-hand side: the only difference is the factor's reuse, which
    // changes nothing in exact arithmetic; both solutions carry round-off of about 1e-15.
    const double scale = direct.displacement.cwiseAbs().maxCoeff();
    CHECK((two.statics.displacement - direct.displacement).cwiseAbs().maxCoeff() <=
          1e-12 * scale);
    for (const char* support : {"A", "B", "C"})
      CHECK(two.statics.reaction(support, Dof::uy) ==
            doctest::Approx(direct.reaction(support, Dof::uy)).epsilon(1e-12).scale(kQ * kL));
  }

  TEST_CASE("the envelope along a member against the closed forms of pattern loading") {
    const Study s = test::solveDeckText(twoSpanDeck(kCases), "two_span.yaml");
    const RunResult& run = onlyRun(s);
    std::vector<LoadedSolution> combinations;
    std::vector<std::string> names;
    for (const CaseOutcome& c : casesOf(run.analyses.front()))
      if (c.combination) {
        combinations.push_back(c.on(*run.model));
        names.push_back(c.name);
      }
    REQUIRE(combinations.size() == 3);
    const std::vector<int>& span1 = run.model->members().front().second;
    // Only the element ends as even places: the sagging peaks lie inside elements, so the
    // envelope reaches them only through the places of the largest values it adds.
    const std::vector<EnvelopeStation> env = memberEnvelope(combinations, span1, 1);
    double sagging = -1e300, hogging = 1e300;
    std::string saggingBy, hoggingBy;
    for (const EnvelopeStation& st : env) {
      // At every place, the largest and smallest over the combinations, each recomputed here
      // from the element's own resultants under the combination's span loads.
      double hi = -1e300, lo = 1e300;
      for (const LoadedSolution& sol : combinations) {
        const double mz = sol.forceSeries(st.element).at(st.s).Mz;
        hi = std::max(hi, mz), lo = std::min(lo, mz);
      }
      CHECK(st.max[5] == doctest::Approx(hi).epsilon(1e-14).scale(kQ * kL * kL));
      CHECK(st.min[5] == doctest::Approx(lo).epsilon(1e-14).scale(kQ * kL * kL));
      if (st.max[5] > sagging) sagging = st.max[5], saggingBy = names[st.maxBy[5]];
      if (st.min[5] < hogging) hogging = st.min[5], hoggingBy = names[st.minBy[5]];
    }
    // Two equal spans, uniform p1 on span 1 and p2 on span 2 (three-moment equation):
    // M_B = -(p1 + p2) L^2 / 16, R_A = p1 L / 2 + M_B / L, largest sagging moment R_A^2/(2 p1).
    const auto supportMoment = [](double p1, double p2) { return -(p1 + p2) * kL * kL / 16; };
    const auto spanMoment = [&](double p1, double p2) {
      const double RA = p1 * kL / 2 + supportMoment(p1, p2) / kL;
      return RA * RA / (2 * p1);
    };
    // Sagging: "left" (1.5 q on span 1 alone) beats ULS (1.35 q, 1.5 q) and both (q, q);
    // hogging: ULS, the largest total load.
    CHECK(saggingBy == "left");
    CHECK(sagging == doctest::Approx(spanMoment(1.5 * kQ, 0)).epsilon(kExact));
    CHECK(spanMoment(1.5 * kQ, 0) > spanMoment(1.35 * kQ, 1.5 * kQ));
    CHECK(hoggingBy == "ULS");
    CHECK(hogging == doctest::Approx(supportMoment(1.35 * kQ, 1.5 * kQ)).epsilon(kExact));
  }

  TEST_CASE("loads: without load cases give no case entries") {
    const Study s = test::solveDeckText(twoSpanDeck("loads: [" + spanLoad("span1", kQ) + "]\n"),
                                        "plain.yaml");
    CHECK(casesOf(onlyRun(s).analyses.front()).empty());
  }

  TEST_CASE("continuous_beam.yaml writes its cases, envelope and cases CSV") {
    const test::SolvedDeck solved =
        test::solveShippedDeckToScratch("continuous_beam.yaml", "continuous-beam");
    const nlohmann::json doc = solved.json("results.json");
    const auto& a = doc["analyses"][0];
    CHECK(a["cases"].size() == 6);  // 3 cases, 3 combinations
    CHECK(a["envelope"]["members"]["span1"]["Mz"]["min"]["case"] == "ULS_both");
    CHECK(a["envelope"]["members"]["span1"]["Mz"]["max"]["case"] == "ULS_span1");
    const std::string csv = solved.text(a["files"]["cases_csv"].get<std::string>());
    CHECK(csv.rfind("case,combination,quantity,at,component,value", 0) == 0);
    CHECK(csv.find("ULS_both,1,member,span1,Mz min,") != std::string::npos);
    // By default only the combinations that govern get a VTK file (FORMAT.md): those that
    // results.json's envelope names for the largest displacement, the largest stress and the
    // largest and smallest Mz of any member.
    std::set<std::string> governing{a["envelope"]["max_displacement"]["case"].get<std::string>(),
                                    a["envelope"]["max_stress"]["case"].get<std::string>()};
    for (const char* extreme : {"max", "min"}) {
      std::string by;
      double top = 0;
      for (const auto& member : a["envelope"]["members"].items()) {
        const double v = member.value()["Mz"][extreme]["value"].get<double>();
        if (by.empty() || (std::string(extreme) == "max" ? v > top : v < top))
          top = v, by = member.value()["Mz"][extreme]["case"].get<std::string>();
      }
      governing.insert(by);
    }
    CHECK(governing == std::set<std::string>{"ULS_both", "ULS_span1"});
    std::set<std::string> written;
    for (const auto& c : a["cases"])
      if (c.contains("vtu")) {
        written.insert(c["name"].get<std::string>());
        CHECK(std::filesystem::exists(solved.dir / c["vtu"].get<std::string>()));
      }
    CHECK(written == governing);
    for (int k = 1; k <= 6; ++k) {
      char name[32];
      std::snprintf(name, sizeof name, "static_case_%02d.vtu", k);
      const bool governs = governing.count(a["cases"][k - 1]["name"].get<std::string>()) > 0;
      CHECK(std::filesystem::exists(solved.dir / name) == governs);
    }
    const std::string pvd = solved.text(a["files"]["cases_pvd"].get<std::string>());
    CHECK(pvd.find("case_04.vtu") != std::string::npos);  // ULS_both, the fourth case
    CHECK(pvd.find("case_01.vtu") == std::string::npos);
    // On request every case and combination has a VTK file whose displacements are the
    // case's own, and the ParaView collection steps through them.
    const Study study = solveStudy(test::shippedDeckRequest("continuous_beam.yaml"));
    const RunResult& run = onlyRun(study);
    const auto& cases = casesOf(run.analyses.front());
    const std::filesystem::path all = solved.dir.parent_path() / "all_cases";
    OutputChoices choices;
    choices.allCases = true;
    choices.charts = ChartFormat::none;
    writeRunOutputs(run, all, choices);
    std::ifstream allJson(all / "results.json");
    const nlohmann::json allDoc = nlohmann::json::parse(allJson);
    const auto& allCases = allDoc["analyses"][0]["cases"];
    REQUIRE(allCases.size() == cases.size());
    for (std::size_t i = 0; i < cases.size(); ++i) {
      vtkNew<vtkXMLUnstructuredGridReader> reader;
      reader->SetFileName((all / allCases[i]["vtu"].get<std::string>()).string().c_str());
      reader->Update();
      vtkDataArray* u = reader->GetOutput()->GetPointData()->GetArray("displacement");
      REQUIRE(u != nullptr);
      REQUIRE(u->GetNumberOfTuples() == cases[i].statics.displacement.rows());
      for (vtkIdType n = 0; n < u->GetNumberOfTuples(); ++n)
        CHECK(u->GetComponent(n, 1) == cases[i].statics.displacement(n, 1));
    }
    std::ifstream allPvd(all / "static_cases.pvd");
    const std::string pvdAll((std::istreambuf_iterator<char>(allPvd)), {});
    for (const char* file : {"case_01.vtu", "case_06.vtu"})
      CHECK(pvdAll.find(file) != std::string::npos);
    // The envelope along each member: its extremes are the results.json envelope's, exactly.
    for (const char* member : {"span1", "span2"}) {
      const std::string env = solved.text(a["files"]["envelope_csv"][member].get<std::string>());
      CHECK(env.rfind("s,element,N_max,N_max_case,N_min,N_min_case", 0) == 0);
      const double hogging = a["envelope"]["members"][member]["Mz"]["min"]["value"].get<double>();
      CHECK(env.find(exactDecimal(hogging)) != std::string::npos);
    }
    std::filesystem::remove_all(solved.dir.parent_path());
  }
}

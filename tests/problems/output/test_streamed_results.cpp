// results.json and the load cases' table as the results directory writes them, a case at a
// time (ResultsDocument::write), against the same run's document made whole by
// prepareRunDocument (the sweeps' path), nlohmann's own dump of the whole tree, and the table
// held whole (wholeResults, the Python module's path); and a NaN met in a case's entry as it is
// written, refused with the same message as the whole tree's check.
#include <doctest/doctest.h>

#include <filesystem>
#include <fstream>
#include <limits>
#include <sstream>
#include <string>

#include "problems/output/JsonWriter.hpp"
#include "problems/output/Output.hpp"
#include "problems/output/PreparedRun.hpp"
#include "problems/output/files/AtomicDirectory.hpp"
#include "tests/problems/DeckTestSupport.hpp"

using namespace beamrotor;
namespace fs = std::filesystem;

// Named, not anonymous: the test sources are compiled in unity batches.
namespace streamed_results {

// A planar portal (fixed bases A and D, a beam B-C) with a horizontal spring at its top, two
// load cases and three combinations: every kind of value a case's entry holds (reactions,
// spring forces, point displacements, member detail).
const std::string kPortal =
    "model: {dimension: planar}\n"
    "materials: [{name: steel, E: 210e9, nu: 0.3, rho: 7850}]\n"
    "sections:\n"
    "  - {name: column, shape: general, A: 78.1e-4, I: 5696e-8, depth: 0.2}\n"
    "  - {name: beam, shape: general, A: 53.8e-4, I: 8356e-8, depth: 0.3}\n"
    "nodes: [{name: A, at: [0, 0]}, {name: B, at: [0, 4]}, {name: C, at: [6, 4]},\n"
    "        {name: D, at: [6, 0]}]\n"
    "members:\n"
    "  - {name: left, from: A, to: B, section: column, elements: 3}\n"
    "  - {name: beam, from: B, to: C, section: beam, elements: 4}\n"
    "  - {name: right, from: D, to: C, section: column, elements: 3}\n"
    "supports: [{name: A, at: A, fix: clamped}, {name: D, at: D, fix: clamped}]\n"
    "springs: [{name: brace, at: C, dof: ux, k: 2e6}]\n"
    "loads: []\n"
    "load_cases:\n"
    "  - {name: lateral, loads: [{type: point, at: B, fx: 10000}]}\n"
    "  - {name: gravity, loads: [{type: distributed, member: beam, qy: -20000}]}\n"
    "combinations:\n"
    "  - {name: both, factors: {lateral: 1, gravity: 1}}\n"
    "  - {name: ULS, factors: {lateral: 1.5, gravity: 1.35}}\n"
    "  - {name: wind, factors: {lateral: -1.5, gravity: 1}}\n"
    "analyses: [{type: static}]\n";

/// The message of the std::runtime_error f throws ("" when none).
template <class F>
std::string errorOf(const F& f) {
  try {
    f();
  } catch (const std::runtime_error& e) {
    return e.what();
  }
  return "";
}

TEST_SUITE("output") {

TEST_CASE("results.json and the cases' table written a case at a time: the whole ones") {
  const Study s = test::solveDeckText(kPortal, "streamed_portal.yaml");
  const RunResult& run = *s.run;
  OutputChoices choices;
  choices.charts = ChartFormat::none;
  choices.units.set("force", "kN");
  choices.units.set("length", "mm");
  PreparedRun prepared = prepareRun(run, choices);
  const fs::path dir = test::scratchDir("streamed_results") / "out";
  writePreparedRun(prepared, dir, choices);

  // The file parses to the document prepareRunDocument makes whole, but for the names of the
  // VTK files written (only the directory's cases have them), which name files that exist.
  Json written = Json::parse(test::fileContents(dir / "results.json"));
  Json& cases = written.at("analyses").at(0).at("cases");
  REQUIRE(cases.size() == 5);
  int named = 0;
  for (Json& c : cases)
    if (c.contains("vtu")) {
      CHECK(fs::exists(dir / c.at("vtu").get<std::string>()));
      c.erase("vtu");
      ++named;
    }
  CHECK(named >= 1);
  CHECK(cases.at(0).contains("members"));  // the member detail is in the entries
  CHECK(cases.at(0).contains("springs"));
  CHECK(written == prepareRunDocument(run));

  // Byte for byte nlohmann's dump of the whole tree (its pretty printing, its numbers).
  const Json whole = wholeResults(prepared);
  CHECK(test::fileContents(dir / "results.json") ==
        whole.dump(2, ' ', false, Json::error_handler_t::replace) + "\n");

  // The load cases' table: the text of the table held whole, in kN and mm, one row a value.
  REQUIRE(prepared.analyses.at(0).caseTable);
  const CsvTable& table = *prepared.analyses.at(0).caseTable;
  std::ostringstream held;
  table.writeTo(held);
  const std::string streamed = test::fileContents(dir / "static_cases.csv");
  CHECK(streamed == held.str());
  CHECK(streamed.find(",reaction,A,fx,") != std::string::npos);
  CHECK(streamed.find(",kN\n") != std::string::npos);
  CHECK(streamed.find(",mm\n") != std::string::npos);
  std::size_t values = 0;
  for (const Json& c : whole.at("analyses").at(0).at("cases"))
    for (const char* key : {"reactions", "springs", "displacements"})
      for (const auto& where : c.at(key).items()) values += where.value().size();
  CHECK(table.rowCount() > values);  // and the members' extremes
  // A reaction's row against the case's own result: the SI value over 1000.
  const CaseOutcome& uls = casesOf(run.analyses.front()).at(3);
  REQUIRE(uls.name == "ULS");
  for (std::size_t row = 0; row < table.rowCount(); ++row)
    if (std::get<std::string>(table.cell(row, 0)) == "ULS" &&
        std::get<std::string>(table.cell(row, 2)) == "reaction" &&
        std::get<std::string>(table.cell(row, 3)) == "D" &&
        std::get<std::string>(table.cell(row, 4)) == "fy")
      CHECK(std::get<double>(table.cell(row, 5)) == uls.statics.reaction("D", Dof::uy) / 1000);
}

TEST_CASE("a NaN in a case's entry: refused as it is written, with the whole tree's message") {
  const Study s = test::solveDeckText(kPortal, "streamed_portal.yaml");
  RunResult run = *s.run;
  // A load case's reaction (the combinations were solved before: the envelope stays finite).
  auto& cases = std::get<StaticOutcome>(run.analyses.front().result).cases;
  REQUIRE(!cases.at(1).combination);
  cases.at(1).statics.reactions.at(0).value = std::numeric_limits<double>::quiet_NaN();
  const std::vector<AnalysisExtremes> extremes = runExtremes(run);
  const ResultsDocument results = runDocument(run, extremes);
  CHECK_NOTHROW(requireFiniteNumbers(results.doc, "results.json"));

  const std::string whole =
      errorOf([&] { requireFiniteNumbers(results.complete(), "results.json"); });
  CHECK(whole.find("results.json: /analyses/0/cases/1/reactions/" +
                   cases.at(1).statics.reactions.at(0).support + "/") == 0);
  CHECK(whole.find("; only finite numbers are written") != std::string::npos);

  // Written into a results directory: the same message, and the earlier results stay.
  const fs::path dir = test::scratchDir("streamed_nan") / "out";
  writeDirectoryAtomically(dir, [&](const fs::path& temporary) {
    std::ofstream(temporary / "results.json") << "earlier\n";
  });
  const std::string streamed = errorOf([&] {
    writeDirectoryAtomically(dir, [&](const fs::path& temporary) {
      results.write(temporary / "results.json");
    });
  });
  CHECK(streamed == whole);
  CHECK(test::fileContents(dir / "results.json") == "earlier\n");
  std::size_t siblings = 0;
  for ([[maybe_unused]] const auto& e : fs::directory_iterator(dir.parent_path())) ++siblings;
  CHECK(siblings == 1);  // no temporary directory left
}

}  // TEST_SUITE

}  // namespace streamed_results

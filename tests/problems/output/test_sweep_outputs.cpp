// A sweep of the cantilever's tip force: sweep.json and sweep.csv follow the closed-form
// reaction P, every value has its own results, and ParaView gets a series over the values.
#include <doctest/doctest.h>

#include <regex>

#include "problems/output/Output.hpp"
#include "tests/problems/output/OutputFixtures.hpp"

using namespace beamrotor;
using namespace beamrotor::test;
namespace fs = std::filesystem;

namespace {

// Exact EB solution: round-off only (see test_run_outputs.cpp).
constexpr double kSweepOutputsExact = 1e-10;

SweepResult tipForceSweep(const std::vector<double>& forces) {
  SweepResult sweep;
  sweep.parameter = "P";
  for (double P : forces) {
    Cantilever c;
    c.P = P;
    sweep.values.push_back(P);
    sweep.runs.push_back(cantileverRun(c, 2));
  }
  return sweep;
}

}  // namespace

TEST_SUITE("output") {
  TEST_CASE("sweep outputs: tables, per-value directories, series and charts") {
    const std::vector<double> forces{500, 1000, 1500};
    const SweepResult sweep = tipForceSweep(forces);
    ScratchDir scratch;
    const fs::path out = scratch / "sweep";
    writeSweepOutputs(sweep, out, {ChartFormat::both, /*pointFiles=*/true});

    const Cantilever c;
    const auto doc = readJson(out / "sweep.json");
    CHECK(doc["parameter"] == "P");
    REQUIRE(doc["runs"].size() == forces.size());
    for (std::size_t i = 0; i < forces.size(); ++i) {
      CAPTURE(i);
      const auto& entry = doc["runs"][i];
      CHECK(entry["value"].get<double>() == forces[i]);
      CHECK(entry["directory"] == "value_00" + std::to_string(i));
      const auto& tip = entry["analyses"][0];
      CHECK(relError(tip["reactions"]["root"]["fy"].get<double>(), forces[i]) < kSweepOutputsExact);
      CHECK(relError(tip["reactions"]["root"]["mz"].get<double>(), forces[i] * c.L) <
            kSweepOutputsExact);
      CHECK(entry["checks"][0]["pass"] == true);
      CHECK(fs::exists(out / entry["directory"].get<std::string>() / "results.json"));
      CHECK(fs::exists(out / entry["directory"].get<std::string>() / "tip.vtu"));
      // Charts only at the sweep level.
      CHECK_FALSE(fs::exists(out / entry["directory"].get<std::string>() / "tip_diagrams.svg"));
    }

    const NumericCsv csv = readNumericCsv(out / "sweep.csv");
    REQUIRE(csv.rows.size() == forces.size());
    const int P = csv.column("P"), fy = csv.column("tip.root.fy"),
              stress = csv.column("tip.max_stress"), f1 = csv.column("modes.f1");
    REQUIRE(P >= 0);
    REQUIRE(fy >= 0);
    REQUIRE(stress >= 0);
    REQUIRE(f1 >= 0);
    for (std::size_t i = 0; i < forces.size(); ++i) {
      CHECK(csv.rows[i][P] == forces[i]);
      CHECK(relError(csv.rows[i][fy], forces[i]) < kSweepOutputsExact);
      // Linear statics: the stress scales with the load; the frequency does not change.
      CHECK(relError(csv.rows[i][stress], csv.rows[0][stress] * forces[i] / forces[0]) <
            kSweepOutputsExact);
      CHECK(csv.rows[i][f1] == csv.rows[0][f1]);
    }

    const std::string pvd = readText(out / "tip.pvd");
    const std::regex dataset("<DataSet timestep=\"([^\"]+)\"[^>]* file=\"([^\"]+)\"");
    std::size_t count = 0;
    for (auto it = std::sregex_iterator(pvd.begin(), pvd.end(), dataset);
         it != std::sregex_iterator(); ++it, ++count) {
      CHECK(std::stod((*it)[1]) == forces.at(count));
      CHECK(fs::exists(out / (*it)[2].str()));
    }
    CHECK(count == forces.size());

    for (const std::string chart : {"sweep_tip", "sweep_modes"}) {
      CAPTURE(chart);
      CHECK(fs::exists(out / (chart + ".svg")));
      CHECK(fs::file_size(out / (chart + ".svg")) > 1000);
    }
  }

  TEST_CASE("a sweep whose values and runs disagree is refused before writing") {
    SweepResult sweep = tipForceSweep({500, 1000});
    sweep.values.push_back(1500);
    ScratchDir scratch;
    CHECK_THROWS_AS(writeSweepOutputs(sweep, scratch / "sweep"), std::invalid_argument);
    CHECK(scratch.entries().empty());
  }

  TEST_CASE("a sweep value whose supports differ from the first is refused before writing") {
    SweepResult sweep = tipForceSweep({500, 1000});
    staticsOf(sweep.runs[1].analyses[0])->reactions[0].support = "elsewhere";
    ScratchDir scratch;
    CHECK_THROWS_AS(writeSweepOutputs(sweep, scratch / "sweep"), std::runtime_error);
    CHECK(scratch.entries().empty());
  }
}

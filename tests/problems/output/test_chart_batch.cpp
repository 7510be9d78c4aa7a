// The charts of a run drawn together: a few gnuplot processes, one per usable core, each
// drawing its share of the scripts in turn; a script gnuplot fails on costs that chart only.
// And the choices of what a results directory holds: --charts, --point-files and the deck's
// `output:` block.
#include <doctest/doctest.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include "problems/output/files/ChartBatch.hpp"
#include "tests/problems/DeckTestSupport.hpp"
#include "tests/problems/output/OutputFixtures.hpp"

using namespace beamrotor;
using namespace beamrotor::test;
namespace fs = std::filesystem;

namespace {

std::vector<std::string> lines(const std::string& text) {
  std::vector<std::string> out;
  std::istringstream in(text);
  for (std::string line; std::getline(in, line);) out.push_back(line);
  return out;
}

ChartScript chart(const std::string& name) { return {name, "batch test", 100, 100, "plot x\n"}; }

}  // namespace

TEST_SUITE("output") {
  TEST_CASE("a batch of charts: one gnuplot per process share, each drawing several scripts") {
    const RecordedCharts recorded;
    const fs::path &dir = recorded.dir, &record = recorded.record;
    std::vector<ChartScript> charts;
    for (const char* name : {"a", "b", "c", "d", "e", "f", "g"}) charts.push_back(chart(name));
    CHECK(drawCharts(dir, charts, ChartFormat::png, 2) == 7);
    const auto starts = lines(readText(record));
    CHECK(starts.size() == 2);  // two processes for seven charts, not seven
    std::size_t scripts = 0;
    for (const std::string& s : starts)
      scripts += std::size_t(std::count(s.begin(), s.end(), ' ')) + 1;
    CHECK(scripts == 7);
    for (const char* name : {"a", "b", "c", "d", "e", "f", "g"}) {
      CHECK(fs::exists(dir / (std::string(name) + ".png")));
      CHECK(fs::exists(dir / (std::string(name) + ".gp")));
      CHECK_FALSE(fs::exists(dir / (std::string(name) + ".log")));
    }
    // Each script draws only the format asked for, from gnuplot's defaults.
    const std::string script = readText(dir / "a.gp");
    CHECK(script.find("do for [format in 'png']") != std::string::npos);
    CHECK(script.find("reset session") != std::string::npos);
  }

  TEST_CASE("a script gnuplot fails on costs that chart only; the rest of its share is drawn") {
    const RecordedCharts recorded("b");
    const fs::path &dir = recorded.dir, &record = recorded.record;
    const std::vector<ChartScript> four{chart("a"), chart("b"), chart("c"), chart("d")};
    CHECK(drawCharts(dir, four, ChartFormat::png, 1) == 3);
    const auto starts = lines(readText(record));
    REQUIRE(starts.size() == 2);  // the share, then what followed the failed script
    CHECK(starts[0] == "./a.gp ./b.gp ./c.gp ./d.gp");
    CHECK(starts[1] == "./c.gp ./d.gp");
    CHECK_FALSE(fs::exists(dir / "b.png"));
    CHECK(readText(dir / "b.log").find("undefined function") != std::string::npos);
    for (const char* name : {"a", "c", "d"}) CHECK(fs::exists(dir / (std::string(name) + ".png")));
  }

  TEST_CASE("inside a ChartBatch, drawChart hands the chart over; none draws nothing") {
    const RecordedCharts recorded;
    const fs::path &dir = recorded.dir, &record = recorded.record;
    {
      ChartBatch none(ChartFormat::none);
      CHECK_FALSE(drawChart(dir, chart("n")));
      CHECK(none.draw() == 0);
    }
    CHECK_FALSE(fs::exists(dir / "n.gp"));
    ChartBatch batch(ChartFormat::png);
    CHECK(drawChart(dir, chart("x")));
    CHECK(drawChart(dir, chart("y")));
    CHECK_FALSE(fs::exists(record));  // nothing drawn yet
    CHECK(batch.draw() == 2);
    CHECK(lines(readText(record)).size() <= 2);
    CHECK(fs::exists(dir / "x.png"));
  }

  TEST_CASE("--charts, --point-files and the deck's output: block choose the files") {
    const fs::path dir = scratchDir("output-choices");
    const auto files = [](const fs::path& out, const std::string& extension) {
      int n = 0;
      for (const auto& entry : fs::recursive_directory_iterator(out))
        n += entry.path().extension() == extension;
      return n;
    };
    const auto solve = [&](std::vector<std::string> arguments) {
      arguments.insert(arguments.begin(), "solve");
      const ProcessResult r = runBeamrotor(arguments, dir);
      CAPTURE(r.err);
      REQUIRE(r.exitCode == 0);
    };
    const std::string cantilever = (problemsDir() / "cantilever.yaml").string();
    solve({cantilever, "--out", "none", "--charts", "none"});
    for (const char* extension : {".png", ".svg", ".gp"})
      CHECK(files(dir / "none", extension) == 0);
    solve({cantilever, "--out", "svg", "--charts", "svg"});
    CHECK(files(dir / "svg", ".svg") == 2);
    CHECK(files(dir / "svg", ".png") == 0);
    solve({cantilever, "--out", "png"});  // the default
    CHECK(files(dir / "png", ".png") == 2);
    CHECK(files(dir / "png", ".svg") == 0);
    // The deck's choice, and the command line's over it.
    std::ofstream(dir / "deck.yaml") << readText(cantilever)
                                     << "\noutput: {charts: both, point_files: true}\n";
    solve({"deck.yaml", "--out", "deck"});
    CHECK(files(dir / "deck", ".svg") == 2);
    CHECK(files(dir / "deck", ".png") == 2);
    solve({"deck.yaml", "--out", "over", "--charts", "svg"});
    CHECK(files(dir / "over", ".png") == 0);
    // A sweep: its own tables always, each value's directory only on request.
    const std::string pumpRod = (problemsDir() / "pump_rod.yaml").string();
    solve({pumpRod, "--out", "sweep", "--sweep", "eta=0:0.4:7"});
    CHECK(fs::exists(dir / "sweep" / "sweep.csv"));
    CHECK_FALSE(fs::exists(dir / "sweep" / "value_000"));
    CHECK_FALSE(fs::exists(dir / "sweep" / "bending.pvd"));
    solve({pumpRod, "--out", "points", "--sweep", "eta=0:0.4:7", "--point-files"});
    for (int i = 0; i < 8; ++i)
      CHECK(fs::exists(dir / "points" / ("value_00" + std::to_string(i)) / "results.json"));
    CHECK(fs::exists(dir / "points" / "bending.pvd"));
    CHECK(files(dir / "points" / "value_000", ".png") == 0);  // no charts per value
    // A misspelt choice is bad input naming the choices.
    std::ofstream(dir / "bad.yaml") << readText(cantilever) << "\noutput: {charts: jpg}\n";
    const ProcessResult bad = runBeamrotor({"solve", "bad.yaml"}, dir);
    CHECK(bad.exitCode == 2);
    CHECK(bad.err.find("output.charts") != std::string::npos);
    CHECK(bad.err.find("png, svg, both, none") != std::string::npos);
    fs::remove_all(dir);
  }
}

TEST_SUITE("output") {
  TEST_CASE("a long line's fields table is thinned, its steps kept; --full-tables writes all") {
    // A stepped cantilever of 3000 elements (15 000 stations) with a tip force: the shear
    // stress jumps at the step, the shear force is P along the whole length.
    const fs::path dir = scratchDir("thinned-fields");
    std::ofstream(dir / "long.yaml")
        << "parameters: {P: 1 kN}\n"
           "materials: [{name: steel, E: 210 GPa, nu: 0.3, rho: 7850 kg/m^3}]\n"
           "sections: [{name: thick, shape: circle, D: 60 mm}, {name: thin, shape: circle, "
           "D: 40 mm}]\n"
           "segments: [{length: 1 m, section: thick, elements: 1500}, {length: 1 m, section: "
           "thin, elements: 1500}]\n"
           "points: [{name: tip, at: 2 m}]\n"
           "supports: [{name: root, at: start, fix: clamped}]\n"
           "loads: [{type: point, at: tip, fy: -P}]\n"
           "analyses: [{type: static}]\n";
    for (const char* out : {"thinned", "full"}) {
      std::vector<std::string> arguments{"solve", "long.yaml", "--out", out, "--charts", "none"};
      if (std::string(out) == "full") arguments.push_back("--full-tables");
      const ProcessResult r = runBeamrotor(arguments, dir);
      REQUIRE_MESSAGE(r.exitCode == 0, r.err);
    }
    const auto thinned = csvCells(dir / "thinned" / "static_fields.csv");
    const auto full = csvCells(dir / "full" / "static_fields.csv");
    CHECK(full.size() == 1 + 5 * 3000);
    CHECK(thinned.size() <= 1 + 4000);
    CHECK(thinned.size() >= 1 + 3000);
    CHECK(thinned.back() == full.back());  // the tip, as written in full
    CHECK(thinned[1] == full[1]);          // the root
    // The step at x = 1 m: both sides, as the full table has them, so the diagram's step stays.
    const std::size_t x = csvColumn(full.front(), "x");
    const auto atStep = [&](const std::vector<std::vector<std::string>>& table) {
      std::vector<std::vector<std::string>> rows;
      for (std::size_t r = 1; r < table.size(); ++r)
        if (std::abs(std::stod(table[r][x]) - 1) < 1e-12) rows.push_back(table[r]);
      return rows;
    };
    const auto fullStep = atStep(full);
    REQUIRE(fullStep.size() == 2);
    CHECK(fullStep[0] != fullStep[1]);
    CHECK(atStep(thinned) == fullStep);
    fs::remove_all(dir);
  }
}

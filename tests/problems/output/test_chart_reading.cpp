// Every chart the shipped decks draw, looked at as a picture: nothing cut at the image's edge
// (ink on the PNG's border), no two texts printed over each other and none outside the canvas
// (the SVG), no gnuplot warning. The inspection is shown to fail on charts with those faults.
#include <doctest/doctest.h>

#include <filesystem>
#include <string>
#include <vector>

#include "problems/output/files/Gnuplot.hpp"
#include "tests/problems/DeckTestSupport.hpp"
#include "tests/problems/output/ChartInspection.hpp"

using namespace beamrotor;
using namespace beamrotor::test;

namespace {

namespace fs = std::filesystem;

/// Every chart (PNG and SVG) under dir, all faults found, one line each.
std::vector<std::string> chartFaults(const fs::path& dir, int& charts) {
  std::vector<std::string> faults;
  for (const auto& entry : fs::recursive_directory_iterator(dir)) {
    const fs::path& file = entry.path();
    std::vector<std::string> found;
    if (file.extension() == ".png") {
      ++charts;
      found = inkOnImageEdges(file);
    } else if (file.extension() == ".svg") {
      found = textFaults(file);
    }
    for (const std::string& f : found) faults.push_back(file.filename().string() + ": " + f);
  }
  return faults;
}

/// A small chart drawn into dir from gnuplot commands.
void drawTestChart(const fs::path& dir, const std::string& name, const std::string& body) {
  REQUIRE(drawChart(dir, {name, "inspection test", 600, 400, body}));
}

}  // namespace

TEST_SUITE("charts read right") {
  TEST_CASE("the inspection finds cut and overprinted text (it can fail)") {
    const fs::path dir = scratchDir("chart-inspection");
    // A name centred on the plot's right end with a 30 px margin: cut at the image's edge,
    // as the old static diagrams did with a long point name at the end of the line.
    drawTestChart(dir, "cut", "  set rmargin at screen 0.95\n"
                              "  set label 'a long point name' at graph 1, graph 1.04 center\n"
                              "  plot x notitle\n");
    CHECK_FALSE(inkOnImageEdges(dir / "cut.png").empty());
    CHECK_FALSE(textFaults(dir / "cut.svg").empty());
    // A y label pushed off the canvas by long tick labels, as the old sweep charts did.
    drawTestChart(dir, "pushed", "  set lmargin at screen 0.1\n  set format y '%.9f'\n"
                                 "  set ylabel 'phi_error_max [rad]'\n  plot [0:1] x*1e-4 notitle\n");
    CHECK_FALSE(inkOnImageEdges(dir / "pushed.png").empty());
    // Two labels 20 rpm apart, as the old Campbell diagram labelled 1798 and 1812 rpm.
    drawTestChart(dir, "overprinted", "  set label '1798 rpm' at 1798, 30 left\n"
                                      "  set label '1812 rpm' at 1812, 30.4 left\n"
                                      "  plot [0:20000][0:350] x/60 notitle\n");
    CHECK(textFaults(dir / "overprinted.svg").size() == 1);
    CHECK(inkOnImageEdges(dir / "overprinted.png").empty());  // overprinted, but not cut
    // A log axis labelled with a fixed format, as the undamped unbalance chart once printed
    // 1000.0000000: every decade's label is padded (10 to 10000: 4 labels).
    drawTestChart(dir, "padded", "  set logscale y\n  set format y '%.7f'\n"
                                 "  plot [1:2][10:10000] 10**(3*x-2) notitle\n");
    std::size_t padded = 0;
    for (const std::string& fault : textFaults(dir / "padded.svg"))
      padded += fault.find("padded with zeros") != std::string::npos;
    CHECK(padded == 4);
    // A clean chart has no faults (so a fault found is not the method's noise).
    drawTestChart(dir, "clean", "  set xlabel 'x [m]'\n  set ylabel 'y [m]'\n  plot x notitle\n");
    CHECK(inkOnImageEdges(dir / "clean.png").empty());
    CHECK(textFaults(dir / "clean.svg").empty());
    fs::remove_all(dir.parent_path());
  }

  TEST_CASE("every chart of the shipped decks: nothing cut, nothing overprinted, no warning") {
    // The shipped decks as they are, plus the forme shaft rotor on soft bearings (critical
    // speeds 1798 and 1982 rpm, whose labels once overprinted) and in the rigid limit
    // (planar whirl lines, equal amplitudes at every point), and MO-10 without its sweep (the
    // history chart of one run).
    struct Case {
      std::string deck;
      std::vector<std::string> options;
    };
    std::vector<Case> cases;
    for (const fs::path& deck : shippedDecks()) cases.push_back({deck.filename().string(), {}});
    cases.push_back({"forme_shaft_rotor.yaml", {"--set", "C1=3e6"}});
    cases.push_back({"forme_shaft_rotor.yaml", {"--set", "E=2e17"}});
    cases.push_back({"mo10.yaml", {"--no-sweep"}});
    int charts = 0;
    for (const Case& c : cases) {
      CAPTURE(c.deck);
      CAPTURE(c.options.size());
      const fs::path out = scratchDir("chart-reading-" + c.deck) / "out";
      std::vector<std::string> arguments{"solve", "problems/" + c.deck, "--out", out.string(),
                                         "--charts", "both"};
      arguments.insert(arguments.end(), c.options.begin(), c.options.end());
      const ProcessResult solved = runBeamrotor(arguments);
      REQUIRE(solved.exitCode == 0);
      CHECK(solved.err.find("warning") == std::string::npos);
      for (const std::string& fault : chartFaults(out, charts)) FAIL_CHECK(fault);
      fs::remove_all(out.parent_path());
    }
    CHECK(charts >= 18);  // every deck draws at least one; the rotor variants two each
  }
}

// The 3d view of a frame chart stays on its canvas, whatever the frame's proportions: a lone
// vertical column, a tall thin tower and an ordinary frame, each solved by `beamrotor solve`
// with its charts drawn by the recording gnuplot (RecordedCharts), their scripts read back.
//
// What keeps the view on the canvas (seen on the PNGs of these three frames):
// - the box is no taller than it is wide (a cube when the frame is taller): gnuplot's `set view equal xyz` scales all three axes to the larger
//   horizontal range, so a box taller than it is wide (a column has no horizontal extent at
//   all) stands out above and below its panel;
// - the panels take gnuplot's own margins: with screen margins (`layout ... margins`) gnuplot
//   fits the view's unit box to them whatever `set view`'s scale, and the projected cube is
//   about 1.5 times that box tall, so the floor's front corner and its tick labels fell off
//   the bottom.
// Both hold for the old charts' failure: the lone column's script set no horizontal range
// (gnuplot took [-1:1] about a 4 m column) and laid its panels out with screen margins.
#include <doctest/doctest.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <regex>
#include <string>

#include "tests/problems/DeckTestSupport.hpp"
#include "tests/problems/output/OutputFixtures.hpp"

using namespace beamrotor;
namespace fs = std::filesystem;

// Named, not anonymous: the test sources are compiled in unity batches.
namespace frame_view {

std::string frameDeck(const std::string& nodes, const std::string& members) {
  return "model: {dimension: 3d}\n"
         "materials: [{name: steel, E: 210 GPa, nu: 0.3, rho: 7850}]\n"
         "sections: [{name: s, catalog: HEB200}]\n"
         "nodes:\n" + nodes + "members:\n" + members +
         "supports: [{name: base, at: a, fix: clamped}]\n"
         "loads: [{type: point, at: b, fx: 5 kN, fz: 2 kN}]\n"
         "analyses: [{type: static}]\n";
}

/// The numbers of `set NAME [low:high]`, the first such line.
std::pair<double, double> range(const std::string& script, const std::string& name) {
  const std::regex r("set " + name + " \\[([-+0-9.e]+):([-+0-9.e]+)\\]");
  std::smatch m;
  REQUIRE_MESSAGE(std::regex_search(script, m, r), "no set " << name);
  return {std::stod(m[1].str()), std::stod(m[2].str())};
}

/// The static frame chart's script of the deck, drawn by the recording gnuplot.
std::string staticFrameScript(const std::string& deck, const std::string& name) {
  const test::RecordedCharts charts;
  const fs::path file = charts.scratch / (name + ".yaml");
  std::ofstream(file) << deck;
  const fs::path out = charts.scratch / "out";
  const test::ProcessResult r = test::runBeamrotor({"solve", file.string(), "--out", out.string()});
  CAPTURE(r.err);
  REQUIRE(r.exitCode == 0);
  for (const auto& entry : fs::directory_iterator(out))
    if (entry.path().extension() == ".gp" &&
        entry.path().filename().string().find("_frame") != std::string::npos)
      return test::fileContents(entry.path());
  FAIL("no frame chart in " << out.string());
  return {};
}

}  // namespace frame_view

TEST_SUITE("output") {
  TEST_CASE("a 3d frame chart's view fits its panels: a lone column, a tower, a frame") {
    using namespace frame_view;
    const std::string column = frameDeck(
        "  - {name: a, at: [0, 0, 0]}\n  - {name: b, at: [0, 4, 0]}\n",
        "  - {name: col, from: a, to: b, section: s, elements: 4}\n");
    const std::string tower = frameDeck(
        "  - {name: a, at: [0, 0, 0]}\n  - {name: m, at: [0, 30, 0]}\n"
        "  - {name: b, at: [1.5, 30, 0]}\n",
        "  - {name: mast, from: a, to: m, section: s, elements: 6}\n"
        "  - {name: arm, from: m, to: b, section: s, elements: 2}\n");
    const std::string frame = frameDeck(
        "  - {name: a, at: [0, 0, 0]}\n  - {name: b, at: [0, 4, 0]}\n"
        "  - {name: c, at: [6, 4, 0]}\n  - {name: d, at: [6, 0, 0]}\n"
        "  - {name: e, at: [6, 4, 5]}\n  - {name: f, at: [6, 0, 5]}\n",
        "  - {name: c1, from: a, to: b, section: s, elements: 2}\n"
        "  - {name: g1, from: b, to: c, section: s, elements: 2}\n"
        "  - {name: c2, from: d, to: c, section: s, elements: 2}\n"
        "  - {name: g2, from: c, to: e, section: s, elements: 2}\n"
        "  - {name: c3, from: f, to: e, section: s, elements: 2}\n");
    for (const auto& [name, deck] : {std::pair<std::string, std::string>{"column", column},
                                     {"tower", tower},
                                     {"frame", frame}}) {
      CAPTURE(name);
      const std::string script = staticFrameScript(deck, name);
      // Screen margins would void the view's scale and fit the unit box to the panel's plot
      // area, leaving no room for a projection that reaches beyond it.
      CHECK(script.find("set multiplot layout 1,2 title") != std::string::npos);
      CHECK(script.find(" margins ") == std::string::npos);
      // The box no taller than it is wide, square in plan (to the script's six digits): a
      // cube for the column and the tower.
      const auto [x0, x1] = range(script, "xrange");
      const auto [y0, y1] = range(script, "yrange");
      const auto [z0, z1] = range(script, "zrange");
      CHECK(x1 - x0 >= (z1 - z0) * (1 - 1e-5));
      CHECK(y1 - y0 == doctest::Approx(x1 - x0).epsilon(1e-5));
      // Every node inside the box (the column's foot and head, the tower's arm).
      CHECK(x0 < 0);
      CHECK(x1 > 0);
      CHECK(z0 < 0);
      CHECK(z1 > 4);
    }
  }
}

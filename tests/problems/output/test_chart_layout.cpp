// The pieces that make charts read right, against numbers worked out by hand: log axes in
// whole decades, labels kept apart, and a torsion mode charted by its rotation (against the
// closed form of a disk on a torsion spring).
#include <doctest/doctest.h>

#include <cmath>
#include <numbers>
#include <string>

#include "problems/output/files/ChartParts.hpp"
#include "problems/output/structure/Charts.hpp"
#include "problems/output/files/LabelPlacement.hpp"
#include "problems/output/structure/Tables.hpp"
#include "tests/Helpers.hpp"
#include "tests/problems/DeckTestSupport.hpp"

using namespace beamrotor;

namespace {

bool contains(const std::string& text, const std::string& part) {
  return text.find(part) != std::string::npos;
}

// A steel shaft clamped at x = 0 carrying a disk of polar inertia Jp at x = L, in 3D. The disk
// has no mass and no diametral inertia, so the bending modes are the bare cantilever's (first
// near 36 Hz) and the lowest mode is the disk twisting the shaft (near 3.5 Hz).
constexpr const char* kTorsionDeck = R"(
parameters: {L: 1.0, D: 0.05, E: 210e9, nu: 0.3, rho: 7850, Jp: 100}
model: {dimension: 3d}
materials: [{name: steel, E: E, nu: nu, rho: rho}]
sections: [{name: shaft, shape: circle, D: D}]
segments: [{length: L, section: shaft, elements: 10}]
supports: [{name: root, at: start, fix: clamped}]
masses: [{name: disk, at: end, m: 0, Jp: Jp, Jd: 0}]
analyses: [{type: modal, name: vibration, modes: 4}]
)";

}  // namespace

TEST_SUITE("chart layout") {
  TEST_CASE("log axes span whole decades and label powers of ten") {
    // 0.0012 .. 4.5e5 um: log10 from -2.92 to 5.65, so decades 1e-3 .. 1e6 (9 of them); at
    // most eight labels means one every 2 decades (a factor 100).
    const std::string wide = logAxis("y", 0.0012, 4.5e5);
    CHECK(contains(wide, "set yrange [1e-3:1e6]"));
    CHECK(contains(wide, "set ytics 1e-3, 100"));
    CHECK(contains(wide, "set format y '10^{%T}'"));
    // Inside one decade (2000 .. 3000): still the whole decade 1e3 .. 1e4, never ticks such as
    // 2000, 2500 printed with the exponent format.
    CHECK(contains(logAxis("x", 2000, 3000), "set xrange [1e3:1e4]"));
    CHECK(contains(logAxis("x", 2000, 3000), "set xtics 1e3, 10"));
    // Exactly on decades: 1e4 .. 1e6 stays 1e4 .. 1e6.
    CHECK(contains(logAxis("x", 1e4, 1e6), "set xrange [1e4:1e6]"));
    // Nothing positive: a plain log axis in %g, no range.
    CHECK_FALSE(contains(logAxis("y", 0, 0), "range"));
  }

  TEST_CASE("labels of neighbouring points do not overlap and stay in the plot") {
    const PixelBox plot{90, 100, 800, 580};
    // Three crossings a few pixels apart (1798, 1812 and 1982 rpm on a 0..20000 rpm axis of
    // 710 px: 0.5 px and 6 px apart), 48 x 13 px labels.
    const std::vector<PointLabel> labels{
        {153.8, 540, 48, 13}, {154.3, 538, 48, 13}, {160.4, 533, 48, 13}};
    const std::vector<PixelBox> boxes = placeLabels(labels, plot);
    REQUIRE(boxes.size() == 3);
    for (std::size_t i = 0; i < boxes.size(); ++i) {
      CAPTURE(i);
      CHECK(boxes[i].inside(plot));
      CHECK(boxes[i].right - boxes[i].left == doctest::Approx(48));
      for (std::size_t j = i + 1; j < boxes.size(); ++j) CHECK_FALSE(boxes[i].overlaps(boxes[j]));
    }
    // A point at the plot's right edge gets its label on the left.
    const auto edge = placeLabels({{795, 300, 48, 13}}, plot);
    CHECK(edge[0].right <= 795);
  }

  TEST_CASE("a torsion mode is charted by its rotation, linear along a shaft twisted by a disk") {
    const Study study = test::solveDeckText(kTorsionDeck, "torsion.yaml");
    REQUIRE(study.run);
    const RunResult& run = *study.run;
    const ModalResult& modal = *resultOf<ModalResult>(run.analyses.front());
    // Closed form: a disk on the shaft's torsion spring k = G Ip / L, with a third of the
    // shaft's own polar inertia (Rayleigh; exact to the square of rho Ip L / Jp ~ 5e-5).
    const double L = 1.0, D = 0.05, E = 210e9, nu = 0.3, rho = 7850, Jp = 100;
    const double G = E / (2 * (1 + nu)), Ip = std::numbers::pi * std::pow(D, 4) / 32;
    const double f = std::sqrt(G * Ip / L / (Jp + rho * Ip * L / 3)) / (2 * std::numbers::pi);
    // Tolerance: Rayleigh's error (~(5e-5)^2) plus the consistent mass's error on the shaft's
    // share (< 1e-6 of 5e-5): 1e-6 covers both and catches a wrong spring (G or Ip) or inertia.
    CHECK(test::relError(modal.modes[0].frequencyHz, f) < 1e-6);
    MESSAGE("torsion frequency " << modal.modes[0].frequencyHz << " Hz, closed form " << f
                                 << ", rel. error " << test::relError(modal.modes[0].frequencyHz, f));

    const CsvTable shapes = modeShapesTable("shapes", *run.model, modal);
    const auto x = shapes.numbers("x"), twist = shapes.numbers("mode1_rx");
    REQUIRE(x.size() > 10);
    // The shaft's inertia is negligible, so the twist grows linearly from the clamp, largest
    // (1 rad by the display scaling) at the disk; the uniform-shaft solution sin(bx)/sin(bL)
    // departs from x/L by < (bL)^2/6 ~ 1e-5.
    double worst = 0;
    for (std::size_t k = 0; k < x.size(); ++k) worst = std::max(worst, std::abs(twist[k] - x[k] / L));
    CHECK(worst < 2e-5);
    MESSAGE("twist against x/L: largest difference " << worst);
    // Bending modes have no rotation column: their translations are charted.
    CHECK_FALSE(shapes.hasColumn("mode2_rx"));
    const ChartScript chart =
        modeShapesChart("torsion", "shapes", *run.model, modal, shapes, "shapes.csv");
    CHECK(contains(chart.body, ":" + std::to_string(shapes.column("mode1_rx")) + " with lines"));
    CHECK(contains(chart.body, "torsion: largest rotation = 1 rad"));
  }
}

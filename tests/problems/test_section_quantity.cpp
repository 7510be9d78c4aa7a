// The `section NAME PROPERTY` quantity: a catalogue section's figures checked against the
// values the steel tables print (ArcelorMittal Europe, "Sections and merchant bars", IPE 240,
// 270 and 300), each within half a unit of the last printed digit; a typed rectangle's against
// its closed forms b h^3 / 12 and b h^2 / 6; the same quantity as a design study's output
// along a `pick` of designations; and the errors a wrong name or property gives.
#include <doctest/doctest.h>

#include <filesystem>
#include <fstream>
#include <string>

#include "problems/deck/parse/DeckError.hpp"
#include "problems/run/Measure.hpp"
#include "problems/run/Study.hpp"
#include "tests/Helpers.hpp"
#include "tests/problems/DeckTestSupport.hpp"

using namespace beamrotor;

namespace {

/// A planar portal's column of `section` (a catalogue pick among IPE240, IPE270, IPE300) and a
/// beam of a typed 0.1 m x 0.2 m rectangle, with `tail` (checks, a study).
std::string frame(const std::string& tail) {
  return "model: {dimension: planar}\n"
         "materials: [{name: steel, E: 210 GPa, nu: 0.3, rho: 7850}]\n"
         "parameters: {size: 3}\n"
         "sections:\n"
         "  - {name: col, catalog: [IPE240, IPE270, IPE300], pick: size}\n"
         "  - {name: bar, shape: rectangle, b: 0.1, h: 0.2}\n"
         "nodes: [{name: A, at: [0, 0]}, {name: B, at: [0, 4]}, {name: C, at: [3, 4]}]\n"
         "members:\n"
         "  - {name: column, from: A, to: B, section: col, elements: 2}\n"
         "  - {name: beam, from: B, to: C, section: bar, elements: 2}\n"
         "supports: [{name: A, at: A, fix: clamped}]\n"
         "loads: [{type: point, at: C, fy: -1 kN}]\n" +
         tail;
}

/// A check of `quantity` against a printed `value` whose last digit is worth `unit`: the
/// tolerance is half that unit, relative.
std::string printed(const std::string& quantity, double value, double unit,
                    const std::string& units) {
  return "  - {name: " + quantity + ", quantity: " + quantity +
         ", reference: " + std::to_string(value) + " " + units +
         ", tolerance: " + std::to_string(0.5 * unit / value) + "}\n";
}

}  // namespace

TEST_SUITE("section quantity") {
  TEST_CASE("IPE 300's properties as checks pass against the printed table") {
    // IPE 300 as printed: A 53.81 cm^2, Iy 8356 cm^4, Iz 603.8 cm^4, Wel,y 557.1 cm^3,
    // Wel,z 80.50 cm^3, Wpl,y 628.4 cm^3, Wpl,z 125.2 cm^3, It 20.12 cm^4 (the tables' own
    // formula, StandardSections.cpp: 20.1185).
    const std::string checks =
        "checks:\n" + printed("section col A", 53.81, 0.01, "cm^2") +
        printed("section col Iy", 8356, 1, "cm^4") + printed("section col Iz", 603.8, 0.1, "cm^4") +
        printed("section col Wel_y", 557.1, 0.1, "cm^3") +
        printed("section col Wel_z", 80.50, 0.01, "cm^3") +
        printed("section col Wpl_y", 628.4, 0.1, "cm^3") +
        printed("section col Wpl_z", 125.2, 0.1, "cm^3") +
        printed("section col It", 20.12, 0.01, "cm^4") +
        // The typed rectangle: b h^3 / 12 about its strong axis (tables' y-y, the member's
        // local z), h b^3 / 12 about the weak, b h^2 / 6; exact but for round-off.
        "  - {name: bar Iy, quantity: section bar Iy, reference: 6.666666666666667e-5, "
        "tolerance: 1e-12}\n"
        "  - {name: bar Iz, quantity: section bar Iz, reference: 1.6666666666666667e-5, "
        "tolerance: 1e-12}\n"
        "  - {name: bar Wel_y, quantity: section bar Wel_y, reference: 6.666666666666667e-4, "
        "tolerance: 1e-12}\n"
        "  - {name: bar A, quantity: section bar A, reference: 0.02, tolerance: 1e-12}\n";
    const Study s = test::solveDeckText(frame(checks), "sections.yaml");
    const auto runs = test::runsOf(s);
    REQUIRE(runs.size() == 1);
    for (const Check& c : runs.front()->checks)
      MESSAGE(c.name << ": " << c.computed << " against " << c.reference << " ("
                     << (c.computed / c.reference - 1) << ")");
    CHECK(test::checkAllPass(s) == 12);
  }

  TEST_CASE("a design study outputs a catalogue pick's Iy") {
    const auto dir = test::scratchDir("section-study");
    std::ofstream(dir / "study.yaml") << frame(
        "study:\n"
        "  parameters: {size: {values: [1, 2, 3]}}\n"
        "  outputs: [{quantity: section col Iy}]\n");
    const auto p = test::runBeamrotor(
        {"study", (dir / "study.yaml").string(), "--out", (dir / "out").string()});
    REQUIRE_MESSAGE(p.exitCode == 0, p.err);
    const auto rows = test::csvCells(dir / "out" / "study.csv");
    REQUIRE(rows.size() == 4);
    std::size_t column = rows.front().size();
    for (std::size_t j = 0; j < rows.front().size(); ++j)
      if (rows.front()[j].find("section col Iy") != std::string::npos) column = j;
    REQUIRE(column < rows.front().size());
    // IPE 240, 270, 300 as printed: 3892, 5790, 8356 cm^4, each to +-0.5 cm^4.
    const double printedIy[] = {3892e-8, 5790e-8, 8356e-8};
    for (int k = 0; k < 3; ++k) {
      const double v = std::stod(rows[std::size_t(k) + 1][column]);
      MESSAGE("IPE pick " << k + 1 << ": Iy " << v << " m^4");
      CHECK(std::abs(v - printedIy[k]) <= 0.5e-8);
    }
    std::filesystem::remove_all(dir);
  }

  TEST_CASE("a section quantity names a section and a property the reader knows") {
    const auto error = [](const std::string& quantity, const std::string& reference = "1") {
      try {
        (void)test::solveDeckText(frame("checks: [{name: q, quantity: " + quantity +
                                        ", reference: " + reference + ", tolerance: 1}]\n"),
                                  "bad.yaml");
      } catch (const std::exception& e) {
        return std::string(e.what());
      }
      return std::string("no error");
    };
    CHECK(error("section column Iy").find("section") != std::string::npos);
    CHECK(error("section column Iy").find("col") != std::string::npos);
    CHECK(error("section col Ix").find("not a section property") != std::string::npos);
    CHECK(error("section bar Wpl_y").find("only catalogue sections give Wpl") !=
          std::string::npos);
    // A reference in the wrong unit is refused.
    CHECK(error("section col Iy", "1 cm^3").find("m^4") != std::string::npos);
  }
}

// `beamrotor overlay`: the pump rod's variants A and B (problems/pump_rod.yaml,
// problems/pump_rod_hinged.yaml) on one chart at the paper's extreme-right position, their
// fields tables against the paper's left moment (A: 7.66 kN m) and the pin's zero moment (B);
// one panel when a quantity is named; decks it cannot overlay refused as bad input.
#include <doctest/doctest.h>

#include <cmath>
#include <sstream>
#include <string>
#include <vector>

#include "tests/problems/DeckTestSupport.hpp"

using namespace beamrotor;
using namespace beamrotor::test;
namespace fs = std::filesystem;

namespace {

/// The first data row's value of the column whose header starts with `name` (then a space or
/// the end), from a fields CSV.
double firstRowValue(const std::string& csv, const std::string& name) {
  std::istringstream in(csv);
  std::string header, row, cell;
  std::getline(in, header);
  std::getline(in, row);
  if (row.rfind("# units:", 0) == 0) std::getline(in, row);
  std::vector<std::string> heads, cells;
  for (std::istringstream h(header); std::getline(h, cell, ',');) heads.push_back(cell);
  for (std::istringstream r(row); std::getline(r, cell, ',');) cells.push_back(cell);
  for (std::size_t i = 0; i < heads.size() && i < cells.size(); ++i)
    if (heads[i] == name) return std::stod(cells[i]);
  FAIL("no column " << name << " in " << header);
  return 0;
}

}  // namespace

TEST_SUITE("overlay command") {
  TEST_CASE("variants A and B of the pump rod on one chart") {
    const fs::path out = scratchDir("overlay") / "ab";
    const ProcessResult r =
        runBeamrotor({"overlay", (problemsDir() / "pump_rod.yaml").string(),
                      (problemsDir() / "pump_rod_hinged.yaml").string(), "--set", "eta=0.4",
                      "--out", out.string()});
    REQUIRE_MESSAGE(r.exitCode == 0, r.err);
    const std::string a = fileContents(out / "pump_rod_fields.csv");
    const std::string b = fileContents(out / "pump_rod_hinged_fields.csv");
    // The paper's left moment of variant A, 7.66 kN m, to half a unit of its last digit; the
    // pinned end of variant B carries none (round-off of the recovered moment).
    CHECK(std::abs(std::abs(firstRowValue(a, "Mz")) - 7.66e3) <= 5);
    CHECK(std::abs(firstRowValue(b, "Mz")) < 1e-6);
    // One chart reading both tables, all six panels by default.
    const std::string script = fileContents(out / "overlay.gp");
    for (const char* s : {"pump_rod_fields.csv", "pump_rod_hinged_fields.csv", "deflection",
                          "rotation", "bending moment", "normal stress", "shear stress"})
      CHECK(script.find(s) != std::string::npos);
    CHECK(fs::exists(out / "overlay.png"));
    fs::remove_all(out.parent_path());
  }

  TEST_CASE("--quantity moment draws the moment panel alone") {
    const fs::path out = scratchDir("overlay-moment") / "m";
    const ProcessResult r =
        runBeamrotor({"overlay", (problemsDir() / "pump_rod.yaml").string(),
                      (problemsDir() / "pump_rod_hinged.yaml").string(), "--quantity", "moment",
                      "--out", out.string()});
    REQUIRE_MESSAGE(r.exitCode == 0, r.err);
    const std::string script = fileContents(out / "overlay.gp");
    CHECK(script.find("bending moment") != std::string::npos);
    CHECK(script.find("deflection") == std::string::npos);
    CHECK(script.find("normal stress") == std::string::npos);
    fs::remove_all(out.parent_path());
  }

  TEST_CASE("a deck without diagrams along a line, or a single deck, is bad input") {
    const fs::path out = scratchDir("overlay-bad") / "x";
    const ProcessResult noLine =
        runBeamrotor({"overlay", (problemsDir() / "pump_rod.yaml").string(),
                      (problemsDir() / "mo10.yaml").string(), "--out", out.string()});
    CHECK(noLine.exitCode == 2);
    CHECK(noLine.err.find("mo10.yaml") != std::string::npos);
    CHECK(noLine.err.find("no static analysis along a line") != std::string::npos);
    CHECK_FALSE(fs::exists(out));
    const ProcessResult one =
        runBeamrotor({"overlay", (problemsDir() / "pump_rod.yaml").string()});
    CHECK(one.exitCode == 2);
    fs::remove_all(out.parent_path());
  }
}

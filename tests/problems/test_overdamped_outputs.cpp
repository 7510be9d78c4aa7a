// A rotor with an overdamped mode is written, not refused: a Jeffcott rotor whose damper is far
// above critical in one plane (c_crit = 2 sqrt(k m) = 3.5e3 N s/m, cxx = 2e4) and light in the
// other has a real eigenvalue (no finite log decrement) beside a damped mode. Its Campbell table
// once stopped the run ("column 'line1_log_decrement' holds text"). FORMAT.md: the cell is
// empty and results.json holds null; every other decrement is the solver's number, bit for bit.
#include <doctest/doctest.h>

#include <charconv>
#include <cmath>
#include <fstream>
#include <nlohmann/json.hpp>
#include <sstream>
#include <string>
#include <vector>

#include "problems/output/Output.hpp"
#include "problems/run/Study.hpp"
#include "tests/Helpers.hpp"
#include "tests/problems/DeckTestSupport.hpp"

using namespace beamrotor;
using namespace beamrotor::test;
namespace fs = std::filesystem;

namespace {

const char* kOverdampedDeck = R"(
title: Jeffcott rotor, overdamped in y
parameters: {L: 0.8, D: 0.025, m: 8, E: 2.1e11, c_y: 20000, c_z: 50}
model: {dimension: lateral, rotary_inertia: false}
materials: [{name: massless, E: E, nu: 0.3, rho: 7850e-12}]
sections: [{name: shaft, shape: circle, D: D}]
segments: [{length: L, section: shaft, elements: 8}]
points: [{name: disk, at: L / 2}]
supports:
  - {name: left, at: start, fix: [uy, uz]}
  - {name: right, at: end, fix: [uy, uz]}
masses: [{name: disk, at: disk, m: m}]
bearings: [{name: damper, at: disk, cxx: c_y, cyy: c_z}]
analyses:
  - {type: rotor, name: spin, speed_rpm: 1000, modes: 2}
  - {type: campbell, name: campbell, modes: 2, from_rpm: 0, to_rpm: 4000, steps: 4}
)";

/// A CSV file as rows of cells (the tables here hold no quoted commas), header first.
std::vector<std::vector<std::string>> readCells(const fs::path& file) {
  std::ifstream in(file);
  std::vector<std::vector<std::string>> rows;
  for (std::string line; std::getline(in, line);) {
    std::vector<std::string> cells;
    std::istringstream fields(line + ",");
    for (std::string cell; std::getline(fields, cell, ',');) cells.push_back(cell);
    rows.push_back(cells);
  }
  return rows;
}

std::size_t columnOf(const std::vector<std::string>& header, const std::string& name) {
  for (std::size_t c = 0; c < header.size(); ++c)
    if (header[c] == name) return c;
  FAIL("no column " << name);
  return 0;
}

double parsed(const std::string& cell) {
  double x = 0;
  const auto [end, error] = std::from_chars(cell.data(), cell.data() + cell.size(), x);
  REQUIRE((error == std::errc() && end == cell.data() + cell.size()));
  return x;
}

/// An empty cell where the solver's decrement is infinite, else exactly its number.
void checkCell(const std::string& cell, double solved) {
  CAPTURE(cell);
  CAPTURE(solved);
  if (std::isinf(solved))
    CHECK(cell.empty());
  else
    CHECK(parsed(cell) == solved);
}

void checkJson(const nlohmann::json& value, double solved) {
  CAPTURE(value.dump());
  if (std::isinf(solved))
    CHECK(value.is_null());
  else
    CHECK(value.get<double>() == solved);
}

}  // namespace

TEST_SUITE("rotor decks") {
  TEST_CASE("overdamped mode: empty decrement cell and null in JSON, the damped one as solved") {
    StudyRequest request;
    request.deckPath = "overdamped.yaml";
    const Study study = solveStudyText(kOverdampedDeck, request);
    REQUIRE(study.run);
    const RunResult& run = *study.run;
    const fs::path dir = scratchDir("overdamped_outputs");
    REQUIRE_NOTHROW(writeRunOutputs(run, dir));

    const RotorModesResult& spin = *run.analyses.at(0).rotor->modes;
    const CampbellResult& campbell = *run.analyses.at(1).rotor->campbell;
    // The closed forms in each plane: k = 48 E I / L^3, zeta = c / (2 sqrt(k m)).
    const double k = 48 * 2.1e11 * (kPi * std::pow(0.025, 4) / 64) / std::pow(0.8, 3);
    const double zeta = 50 / (2 * std::sqrt(k * 8));
    REQUIRE(20000 / (2 * std::sqrt(k * 8)) > 1);  // the y plane is overdamped
    int overdamped = 0, damped = 0;
    for (const auto& line : campbell.lines)
      for (const RotorMode& m : line) {
        if (std::isinf(m.logDecrement)) {
          ++overdamped;
        } else {
          ++damped;
          CHECK(relError(m.logDecrement, 2 * kPi * zeta / std::sqrt(1 - zeta * zeta)) < 1e-9);
        }
      }
    CHECK(overdamped == 5);  // one line of the two, at each of the 5 speeds
    CHECK(damped == 5);

    // 1. The Campbell table: one row per speed, line l's decrement in its own column.
    const auto rows = readCells(dir / "campbell_campbell.csv");
    REQUIRE(rows.size() == campbell.speeds.size() + 1);
    for (std::size_t l = 0; l < campbell.lines.size(); ++l) {
      const std::size_t c =
          columnOf(rows[0], "line" + std::to_string(l + 1) + "_log_decrement");
      for (std::size_t s = 0; s < campbell.speeds.size(); ++s)
        checkCell(rows.at(s + 1).at(c), campbell.lines[l][s].logDecrement);
    }

    // 2. The modes at one speed.
    const auto modes = readCells(dir / "spin_modes.csv");
    REQUIRE(modes.size() == spin.modes.size() + 1);
    const std::size_t c = columnOf(modes[0], "log_decrement");
    for (std::size_t m = 0; m < spin.modes.size(); ++m)
      checkCell(modes.at(m + 1).at(c), spin.modes[m].logDecrement);

    // 3. results.json: null for the overdamped mode, the number for the other; the charts
    //    were drawn (gnuplot leaves only a log when its script fails).
    std::ifstream in(dir / "results.json");
    const nlohmann::json doc = nlohmann::json::parse(in);
    const auto& spinModes = doc.at("analyses").at(0).at("modes");
    for (std::size_t m = 0; m < spin.modes.size(); ++m)
      checkJson(spinModes.at(m).at("log_decrement"), spin.modes[m].logDecrement);
    const auto& lines = doc.at("analyses").at(1).at("lines");
    for (std::size_t l = 0; l < campbell.lines.size(); ++l)
      for (std::size_t s = 0; s < campbell.speeds.size(); ++s)
        checkJson(lines.at(l).at("log_decrement").at(s), campbell.lines[l][s].logDecrement);
    CHECK(fs::exists(dir / "campbell_stability.svg"));
    fs::remove_all(dir);
  }
}

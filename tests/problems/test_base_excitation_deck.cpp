// The response-spectrum and base-motion analyses through the deck path, on the shipped machine
// base frame (problems/machine_base_frame.yaml, closed forms in its header): every check
// passes, the results reach results.json, the CSV tables and the summary; bad input is refused
// naming the deck's line and field.
#include <doctest/doctest.h>

#include <vtkDataArray.h>
#include <vtkFieldData.h>
#include <vtkNew.h>
#include <vtkPointData.h>
#include <vtkUnstructuredGrid.h>
#include <vtkXMLUnstructuredGridReader.h>

#include <cmath>
#include <numbers>
#include <sstream>
#include <string>

#include "problems/run/Study.hpp"
#include "tests/problems/DeckTestSupport.hpp"

using namespace beamrotor;

namespace {

const char* const kLine = R"(model: {dimension: planar}
materials: [{name: steel, E: 210e9, nu: 0.3, rho: 7850}]
sections: [{name: rod, shape: circle, D: 0.03}]
segments: [{length: 1, section: rod, elements: 4}]
supports: [{name: root, at: start, fix: clamped}]
points: [{name: tip, at: 1}]
analyses:
)";

}  // namespace

TEST_SUITE("base excitation decks") {
  TEST_CASE("machine base frame: checks pass; results.json, CSV and summary carry the peaks") {
    CHECK(test::checkAllPass(test::solveShippedDeck("machine_base_frame.yaml")) == 11);
    const test::SolvedDeck solved =
        test::solveShippedDeckToScratch("machine_base_frame.yaml", "base-excitation-deck");
    const nlohmann::json results = solved.json("results.json");
    nlohmann::json quake, shaking;
    for (const auto& a : results["analyses"]) {
      if (a["name"] == "quake") quake = a;
      if (a["name"] == "shaking") shaking = a;
    }
    REQUIRE(quake.is_object());
    REQUIRE(shaking.is_object());
    // The deck's closed forms: M Sa with Sa = 2.5 ag S on the plateau (ground C, S = 1.15).
    const double Sa = 2.5 * 0.25 * 9.80665 * 1.15, M = 16000;
    // The deck checks these to 1e-9; here they only need to reach the file as computed.
    CHECK(quake["combined"]["base_force_n"]["x"].get<double>() ==
          doctest::Approx(M * Sa).epsilon(1e-9));
    CHECK(quake["captured_mass_fraction"]["x"].get<double>() == doctest::Approx(1).epsilon(1e-9));
    CHECK(quake["modal_combination"] == "CQC");
    CHECK(quake["directional_combination"] == "100/30");
    CHECK(shaking["points"].contains("B3"));
    const auto modes = test::csvCells(solved.dir / "quake_spectrum_modes.csv");
    REQUIRE(modes.size() == 4);  // header and 3 modes
    CHECK(std::stod(modes[3][test::csvColumn(modes[0], "cumulative_x")]) ==
          doctest::Approx(1).epsilon(1e-9));
    const auto sweep = test::csvCells(solved.dir / "shaking_base_motion.csv");
    CHECK(sweep.size() == 202);  // header and 201 frequencies
    for (const char* file : {"quake_spectrum.png", "quake_spectrum.vtu", "quake_spectrum_members.csv",
                             "quake_spectrum_reactions.csv", "shaking_base_motion.png"})
      CHECK(std::filesystem::exists(solved.dir / file));
    CHECK(solved.process.out.find("combined peaks: base force") != std::string::npos);
    CHECK(solved.process.out.find("transmissibility max") != std::string::npos);
    // Mode 3 twists the frame about y: by symmetry it moves no mass along x or z (the solve
    // leaves 8e-28 kg of the 16,000), so its effective masses read 0 and mode 2 holds all of x.
    const std::string& out = solved.process.out;
    const std::size_t mode3 = out.find("    3     ", out.find("m_x [kg]"));
    REQUIRE(mode3 != std::string::npos);
    std::istringstream row(out.substr(mode3, out.find('\n', mode3) - mode3));
    std::string index, f, T, sa, mx, sumx, percent, mz;
    row >> index >> f >> T >> sa >> mx >> sumx >> percent >> mz;
    CHECK(mx == "0");
    CHECK(mz == "0");
    std::filesystem::remove_all(solved.dir.parent_path());
  }

  TEST_CASE("base motion's VTK file at the peak frequency: read back, the same as results.json") {
    const Study study = test::solveShippedDeck("machine_base_frame.yaml");
    const Model& model = *study.run->model;
    const test::SolvedDeck solved =
        test::solveShippedDeckToScratch("machine_base_frame.yaml", "base-motion-vtk");
    const nlohmann::json results = solved.json("results.json");
    for (const auto& a : results["analyses"]) {
      if (a["type"] != "base-motion") continue;
      CAPTURE(a["name"].get<std::string>());
      // The peak: the sweep's largest base force.
      const auto& force = a["base_force_n"];
      std::size_t peak = 0;
      for (std::size_t i = 0; i < force.size(); ++i)
        if (force[i].get<double>() > force[peak].get<double>()) peak = i;
      CHECK(a["peak_frequency_hz"].get<double>() == a["frequencies_hz"][peak].get<double>());
      vtkNew<vtkXMLUnstructuredGridReader> reader;
      reader->SetFileName((solved.dir / a["vtu"].get<std::string>()).string().c_str());
      reader->Update();
      vtkUnstructuredGrid* grid = reader->GetOutput();
      REQUIRE(grid->GetNumberOfPoints() == model.nodeCount());
      vtkDataArray* frequency = grid->GetFieldData()->GetArray("frequency [Hz]");
      vtkDataArray* base = grid->GetFieldData()->GetArray("base force [N]");
      REQUIRE(frequency);
      REQUIRE(base);
      // Binary doubles against the JSON's shortest round-trip decimals: the same doubles.
      CHECK(frequency->GetTuple1(0) == a["peak_frequency_hz"].get<double>());
      CHECK(base->GetTuple1(0) == force[peak].get<double>());
      vtkDataArray* T = grid->GetPointData()->GetArray("transmissibility [1]");
      vtkDataArray* relative = grid->GetPointData()->GetArray("relative amplitude [m]");
      vtkDataArray* absolute = grid->GetPointData()->GetArray("absolute amplitude [m]");
      REQUIRE(T);
      REQUIRE(relative);
      REQUIRE(absolute);
      int compared = 0;
      for (const auto& [point, values] : a["points"].items()) {
        const int node = model.node(point);
        CHECK(T->GetTuple1(node) == values["transmissibility"][peak].get<double>());
        CHECK(relative->GetComponent(node, 0) == values["relative_m"][peak].get<double>());
        CHECK(absolute->GetComponent(node, 0) == values["absolute_m"][peak].get<double>());
        ++compared;
      }
      CHECK(compared > 0);
    }
    std::filesystem::remove_all(solved.dir.parent_path());
  }

  TEST_CASE("bad input is refused with its line and field") {
    struct Case {
      std::string entry, field;
      int line;
    };
    const Case cases[] = {
        {"  - {type: response-spectrum, spectrum: {code: EN1998-1, type: 1, ground: F, ag: 2}}\n",
         "ground", 8},
        {"  - {type: response-spectrum, spectrum: {code: EN1998-1, type: 1, ground: B, ag: 2 m}}\n",
         "ag", 8},
        {"  - {type: response-spectrum, spectrum: {code: EN1998-1, type: 1, component: vertical, "
         "ground: B, ag: 2}}\n",
         "ground", 8},
        {"  - {type: response-spectrum, spectrum: {code: EN1998-1, type: 1, component: up, "
         "ag: 2}}\n",
         "component", 8},
        {"  - {type: response-spectrum, damping: 1.5, spectrum: {table: [[0, 1], [1, 1]]}}\n",
         "damping", 8},
        {"  - {type: response-spectrum, spectrum: {table: [[0, 1], [0, 1]]}}\n", "table", 8},
        {"  - {type: response-spectrum, directions: [z], spectrum: {table: [[0, 1], [1, 1]]}}\n",
         "directions", 8},
        {"  - {type: base-motion, direction: y, acceleration: 1, displacement: 1, from_hz: 1, "
         "to_hz: 2, damping: 0.02}\n",
         "analyses[0]", 8},
        {"  - {type: base-motion, direction: y, acceleration: 1, from_hz: 1, to_hz: 2}\n",
         "analyses[0]", 8},
        {"  - {type: base-motion, direction: y, acceleration: 1, from_hz: 3, to_hz: 2, "
         "damping: 0.1}\n",
         "to_hz", 8},
        {"  - {type: base-motion, direction: y, acceleration: 1, from_hz: 1, to_hz: 2, "
         "method: direct, damping: 0.1}\n",
         "damping", 8},
    };
    for (const Case& c : cases) {
      CAPTURE(c.entry);
      const DeckError e = test::readingError(std::string(kLine) + c.entry, "shake.yaml");
      CAPTURE(e.message());
      CHECK(e.place().line == c.line);
      CHECK(std::string(e.what()).find(c.field) != std::string::npos);
    }
  }

  TEST_CASE("a mode outside the spectrum table reads the table's nearer end, with a warning") {
    // The rod's two modes (21.7 Hz and about 140 Hz, periods 0.046 and 0.007 s) lie below the
    // table's first period: both read its first value, 1 m/s^2, not the 2 m/s^2 at its end.
    const std::string deck = std::string(kLine) +
                             "  - {type: response-spectrum, modes: 2, directions: [y], "
                             "spectrum: {table: [[0.5, 1], [1, 2]]}}\n";
    const Study s = test::solveDeckText(deck, "shake.yaml");
    const auto* r = resultOf<ResponseSpectrumResult>(s.run->analyses.front());
    REQUIRE(r);
    REQUIRE(r->spectralAcceleration.size() == 2);
    for (double Sa : r->spectralAcceleration) CHECK(Sa == 1.0);
    int outside = 0;
    for (const std::string& w : r->warnings)
      if (w.find("outside the spectrum table's 0.5 to 1 s: it reads the table's first value") !=
          std::string::npos)
        ++outside;
    CHECK(outside == 2);
  }

  TEST_CASE("the vertical spectrum from the deck: each mode's Sa on (3.8) by hand") {
    // The rod's modes (periods 0.046 and 0.007 s) lie below TB = 0.05 s: Sa = avg (1 + T / TB
    // (3 eta - 1)) with avg = 0.9 ag, eta = 1 (Table 3.4, (3.8)).
    const std::string deck = std::string(kLine) +
                             "  - {type: response-spectrum, modes: 2, directions: [y], "
                             "spectrum: {code: EN1998-1, type: 1, component: vertical, "
                             "ag: 2 m/s^2}}\n";
    const Study s = test::solveDeckText(deck, "shake.yaml");
    const auto* r = resultOf<ResponseSpectrumResult>(s.run->analyses.front());
    REQUIRE(r);
    REQUIRE(r->spectralAcceleration.size() == 2);
    for (std::size_t j = 0; j < 2; ++j) {
      const double T = 2 * std::numbers::pi / std::sqrt(r->modal.modes[j].eigenvalue);
      CHECK(r->spectralAcceleration[j] == doctest::Approx(1.8 * (1 + T / 0.05 * 2)).epsilon(1e-12));
    }
  }
}

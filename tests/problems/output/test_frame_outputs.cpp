// What a frame deck writes: results.json's member extremes with their places and the largest
// displacement, one CSV per member, the VTK member axes and section size, and the frame
// chart; numbers against the closed form of problems/frame3d.yaml (see its header).
#include <doctest/doctest.h>
#include <Eigen/Dense>
#include <vtkCell.h>
#include <vtkCellData.h>
#include <vtkDataArray.h>
#include <vtkNew.h>
#include <vtkPointData.h>
#include <vtkUnstructuredGrid.h>
#include <vtkXMLUnstructuredGridReader.h>

#include <cmath>
#include <algorithm>
#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include "problems/deck/DeckReader.hpp"
#include "problems/deck/parse/DeckSource.hpp"
#include "tests/Helpers.hpp"
#include "tests/problems/DeckTestSupport.hpp"

using namespace beamrotor;
using beamrotor::test::relError;
namespace fs = std::filesystem;

namespace {

// EB elements are exact for the base frame's point load; the results pass through JSON at 17
// digits. 1e-9 as in the deck's own checks.
constexpr double kFrameOutputExact = 1e-9;

double frameDeckValue(const std::string& name) {
  const Deck deck =
      readDeck(loadDeckFile(test::problemsDir() / "frame3d.yaml"), {});
  return test::deckValue(deck, name);
}

}  // namespace

TEST_SUITE("output") {
  TEST_CASE("a 3d frame's results: member extremes and places, CSV per member, VTK axes") {
    const test::SolvedDeck solved = test::solveShippedDeckToScratch("frame3d.yaml", "frame_out");
    const auto results = solved.json("results.json");
    const auto& statics = results["analyses"][0];
    const double a = frameDeckValue("a"), b = frameDeckValue("b"), W = frameDeckValue("W"),
                 Me = frameDeckValue("Me"), dp = frameDeckValue("dp");

    // The largest displacement: the pump, at the cross tube's middle (a/2, 0, b/2).
    const auto& top = statics["max_displacement"];
    CHECK(relError(top["value"].get<double>(), dp) < kFrameOutputExact);
    CHECK(std::abs(top["x"].get<double>() - a / 2) < 1e-9 * a);
    CHECK(std::abs(top["z"].get<double>() - b / 2) < 1e-9 * b);

    // The rail's torque is constant, M_e / 2 (either sign: the member's own axis decides).
    const auto& rail = statics["members"]["rail1a"];
    CHECK(relError(std::abs(rail["T"]["max"]["value"].get<double>()), Me / 2) < kFrameOutputExact);
    CHECK(relError(rail["T"]["min"]["value"].get<double>(), rail["T"]["max"]["value"].get<double>()) <
          kFrameOutputExact);
    CHECK(rail["from"] == "A");
    CHECK(rail["to"] == "M1");
    CHECK(std::abs(rail["length"].get<double>() - a / 2) < 1e-12);

    // The cross tube: moment W b / 4 - M_e at the pump (s = b / 2, inside an element of the 3)
    // and M_e of the other sign at its ends.
    const auto& cross = statics["members"]["cross"]["Mz"];
    const double mid = W * b / 4 - Me;
    const auto& sag = std::abs(cross["max"]["value"].get<double>()) >
                              std::abs(cross["min"]["value"].get<double>())
                          ? cross["max"]
                          : cross["min"];
    CHECK(relError(std::abs(sag["value"].get<double>()), std::max(mid, Me)) < kFrameOutputExact);
    if (mid > Me) CHECK(std::abs(sag["s"].get<double>() - b / 2) < 1e-9 * b);
    CHECK(cross["max"]["value"].get<double>() * cross["min"]["value"].get<double>() < 0);

    // One CSV per member with the resultants and the member axes; files named in results.json.
    const std::string csv = statics["members"]["cross"]["csv"];
    CHECK(csv == "static_member_cross.csv");
    const std::string table = solved.text(csv);
    CHECK(table.find("Mz") != std::string::npos);
    CHECK(table.find("ey_x") != std::string::npos);
    // The names and units lines, then 5 stations (4 intervals) per element of the member.
    const long elements = statics["members"]["cross"]["elements"].get<long>();
    CHECK(elements >= 2);  // the pump's station cuts the tube in two at least
    CHECK(std::count(table.begin(), table.end(), '\n') == 2 + 5 * elements);

    // VTK: the element axes and the tube radius per point (the rail's outer radius at A).
    vtkNew<vtkXMLUnstructuredGridReader> reader;
    reader->SetFileName((solved.dir / "static.vtu").string().c_str());
    reader->Update();
    vtkUnstructuredGrid* grid = reader->GetOutput();
    for (const char* name : {"local_x", "local_y", "local_z", "outer_y", "outer_z"})
      CHECK(grid->GetCellData()->GetArray(name) != nullptr);
    vtkDataArray* radius = grid->GetPointData()->GetArray("tube_radius");
    REQUIRE(radius != nullptr);
    CHECK(radius->GetTuple1(0) == doctest::Approx(frameDeckValue("Dr") / 2).epsilon(1e-12));
    // The chart of the whole frame replaces the diagrams along a line.
    CHECK(fs::exists(solved.dir / "static_frame.gp"));
    CHECK_FALSE(fs::exists(solved.dir / "static_diagrams.gp"));
    fs::remove_all(solved.dir.parent_path());
  }

  TEST_CASE("rigid ties in the VTK files and the frame charts, moving as rigid bodies") {
    // Two clamped columns, their tops B0 and B1 a diaphragm in x-z, a beam between them on
    // end offsets (its end arm hangs from B1, which follows B0: a chain), and a bracket tip T
    // linked to B1 (another chain), loaded at T. Four ties: two offsets, the diaphragm's one
    // follower and the bracket.
    const fs::path dir = test::scratchDir("tie_outputs");
    {
      std::ofstream deck(dir / "ties.yaml");
      deck << "model: {dimension: 3d}\n"
              "materials: [{name: steel, E: 210 GPa, nu: 0.3, rho: 7850 kg/m^3}]\n"
              "sections: [{name: bar, shape: circle, D: 100 mm}]\n"
              "nodes:\n"
              "  - {name: A0, at: [0, 0, 0]}\n"
              "  - {name: A1, at: [3, 0, 0]}\n"
              "  - {name: B0, at: [0, 3, 0]}\n"
              "  - {name: B1, at: [3, 3, 0]}\n"
              "  - {name: T, at: [3.6, 3.2, 0.4]}\n"
              "members:\n"
              "  - {name: c0, from: A0, to: B0, section: bar, elements: 2}\n"
              "  - {name: c1, from: A1, to: B1, section: bar, elements: 2}\n"
              "  - {name: beam, from: B0, to: B1, section: bar, elements: 2,\n"
              "     offsets: {start: [0.1 m, 0, 0], end: [-0.1 m, 0, 0]}}\n"
              "supports:\n"
              "  - {name: A0, at: A0, fix: clamped}\n"
              "  - {name: A1, at: A1, fix: clamped}\n"
              "diaphragms: [{name: deck, master: B0, points: [B1], plane: xz}]\n"
              "rigid_links: [{name: bracket, master: B1, slave: T}]\n"
              "loads: [{type: point, at: T, fx: 2 kN, fy: -5 kN, fz: 3 kN}]\n"
              "analyses: [{type: static}, {type: modal, modes: 3}]\n";
    }
    const test::ProcessResult run = test::runBeamrotor(
        {"solve", (dir / "ties.yaml").string(), "--out", (dir / "out").string()});
    CAPTURE(run.err);
    REQUIRE(run.exitCode == 0);

    // The tie cells: after the line elements, kind 1 (the elements 0), element -1, between
    // each master and follower (by their coordinates).
    struct Tie {
      Eigen::Vector3d master, follower;
      bool allDofs;
    };
    // In the model's order: the members' offsets, the links, the diaphragms' followers.
    const std::vector<Tie> ties{{{0, 3, 0}, {0.1, 3, 0}, true},
                                {{3, 3, 0}, {2.9, 3, 0}, true},
                                {{3, 3, 0}, {3.6, 3.2, 0.4}, true},
                                {{0, 3, 0}, {3, 3, 0}, false}};
    for (const std::string file : {"static.vtu", "modal_mode_01.vtu"}) {
      CAPTURE(file);
      double worst = 0;  // the largest departure from the rigid motion, over the largest u
      vtkNew<vtkXMLUnstructuredGridReader> reader;
      reader->SetFileName((dir / "out" / file).string().c_str());
      reader->Update();
      vtkUnstructuredGrid* grid = reader->GetOutput();
      const vtkIdType cells = grid->GetNumberOfCells();
      REQUIRE(cells == 6 + 4);  // six elements, four ties
      vtkDataArray* kind = grid->GetCellData()->GetArray("kind");
      vtkDataArray* element = grid->GetCellData()->GetArray("element");
      REQUIRE(kind);
      REQUIRE(element);
      for (vtkIdType c = 0; c < cells; ++c) {
        CHECK(kind->GetTuple1(c) == (c < 6 ? 0 : 1));
        if (c >= 6) CHECK(element->GetTuple1(c) == -1);
      }
      const bool modal = file != "static.vtu";
      vtkDataArray* u = grid->GetPointData()->GetArray(modal ? "mode_shape" : "displacement");
      vtkDataArray* theta = grid->GetPointData()->GetArray(modal ? "mode_rotation" : "rotation");
      REQUIRE(u);
      REQUIRE(theta);
      double largest = 0;
      for (vtkIdType p = 0; p < grid->GetNumberOfPoints(); ++p)
        for (int k = 0; k < 3; ++k) largest = std::max(largest, std::abs(u->GetComponent(p, k)));
      REQUIRE(largest > 0);
      for (std::size_t t = 0; t < ties.size(); ++t) {
        CAPTURE(t);
        vtkCell* cell = grid->GetCell(vtkIdType(6 + t));
        REQUIRE(cell->GetNumberOfPoints() == 2);
        const vtkIdType m = cell->GetPointId(0), f = cell->GetPointId(1);
        Eigen::Vector3d xm, xf, um, uf, rm, rf;
        grid->GetPoint(m, xm.data());
        grid->GetPoint(f, xf.data());
        CHECK((xm - ties[t].master).norm() <= 1e-12);
        CHECK((xf - ties[t].follower).norm() <= 1e-12);
        for (int k = 0; k < 3; ++k) {
          um[k] = u->GetComponent(m, k), uf[k] = u->GetComponent(f, k);
          rm[k] = theta->GetComponent(m, k), rf[k] = theta->GetComponent(f, k);
        }
        // The follower's tied dofs move with the master as a rigid body: u_m + theta_m x r
        // (all of them, or the diaphragm's ux, uz and ry); an exact elimination and Float64
        // written: round-off, 1e-12 of the largest translation.
        const Eigen::Vector3d rigid = um + rm.cross(xf - xm);
        const std::vector<int> translations =
            ties[t].allDofs ? std::vector<int>{0, 1, 2} : std::vector<int>{0, 2};
        for (int k : translations) {
          CHECK(std::abs(uf[k] - rigid[k]) <= 1e-12 * largest);
          worst = std::max(worst, std::abs(uf[k] - rigid[k]) / largest);
        }
        const double turn = ties[t].allDofs ? (rf - rm).norm() : std::abs(rf[1] - rm[1]);
        CHECK(turn <= 1e-12 * largest);
        worst = std::max(worst, turn / largest);
      }
      MESSAGE(file << ": followers off their masters' rigid motion by " << worst
                   << " of the largest translation");
    }

    // The charts draw the four ties (one curve of two places each) and say so.
    for (const char* chart : {"static_frame.gp", "modal_shapes.gp"}) {
      CAPTURE(chart);
      const std::string text = test::fileContents(dir / "out" / chart);
      const std::string block = std::string(chart) == "static_frame.gp" ? "$ties << EOD\n"
                                                                          : "$ties1 << EOD\n";
      const std::size_t start = text.find(block);
      REQUIRE(start != std::string::npos);
      const std::size_t end = text.find("EOD\n", start + block.size());
      REQUIRE(end != std::string::npos);
      const std::string data = text.substr(start + block.size(), end - start - block.size());
      std::size_t places = 0;
      for (std::size_t at = 0; (at = data.find('\n', at)) != std::string::npos; ++at)
        places += at > 0 && data[at - 1] != '\n';
      CHECK(places == 8);
      CHECK(text.find("rigid ties dashed") != std::string::npos);
    }
    fs::remove_all(dir.parent_path());
  }
}

// What a frame deck writes: results.json's member extremes with their places and the largest
// displacement, one CSV per member, the VTK member axes and section size, and the frame
// chart; numbers against the closed form of problems/frame3d.yaml (see its header).
#include <doctest/doctest.h>
#include <vtkCellData.h>
#include <vtkDataArray.h>
#include <vtkNew.h>
#include <vtkPointData.h>
#include <vtkUnstructuredGrid.h>
#include <vtkXMLUnstructuredGridReader.h>

#include <cmath>
#include <algorithm>
#include <filesystem>

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
}

// Mode and buckling shapes of frames: described by the rigid motion their effective mass
// follows, on a one-storey 3d frame whose modes are known (a shear building: four light
// columns, nearly rigid beams, a mass at each top corner): sway along z, torsion about y, sway
// along x, each frequency against the closed form of the three-dof model; a planar portal's
// sway buckling mode; and the shapes CSV of a frame at the places' coordinates.
#include <doctest/doctest.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <numbers>
#include <sstream>
#include <string>

#include "problems/output/structure/StabilityOutput.hpp"
#include "problems/run/Study.hpp"
#include "tests/problems/DeckTestSupport.hpp"

using namespace beamrotor;

namespace {

// Columns h tall at the corners of an a x a plan, clamped at their feet; the beams joining
// their tops 10^4 times stiffer than the columns; mass M at each top corner (the members'
// own mass 10^-9 of it); the columns' area large (1 m^2), since their axial strain under the
// overturning moment softens the sway by 3e-3 at a steel column's area. A column (along +y; local y = -x, local z = +z) resists a top
// translation along x with k_x = 12 E Iz / h^3 and along z with k_z = 12 E Iy / h^3 (both
// ends clamped: the beams hold the tops from turning). Three-dof model: omega_x^2 = k_x / M,
// omega_z^2 = k_z / M and, turning the roof by theta about y through its centre (every corner
// a / sqrt(2) from it, each column twisted by theta too),
// omega_t^2 = ((k_x + k_z) a^2 + 4 G J / h) / (2 M a^2).
constexpr double kA = 4, kH = 3, kM = 1000, kE = 210e9, kNu = 0.3;
constexpr double kIz = 2e-5, kIy = 1e-5, kJ = 1e-6;

std::string shearBuilding() {
  std::ostringstream d;
  d.precision(17);
  d << "model: {dimension: 3d}\n"
    << "materials:\n"
    << "  - {name: steel, E: " << kE << ", nu: " << kNu << ", rho: 1e-9}\n"
    << "  - {name: stiff, E: " << 1e4 * kE << ", nu: " << kNu << ", rho: 1e-9}\n"
    << "sections:\n"
    << "  - {name: column, material: steel, shape: general, A: 1, Iz: " << kIz
    << ", Iy: " << kIy << ", J: " << kJ << ", depth: 0.2, width: 0.1}\n"
    << "  - {name: beam, material: stiff, shape: general, A: 5e-3, I: 1e-4, J: 1e-4, depth: "
       "0.3, width: 0.2}\n";
  std::ostringstream& n = d;
  n << "nodes:\n";
  const char* names[4] = {"1", "2", "3", "4"};
  const double xs[4] = {0, kA, kA, 0}, zs[4] = {0, 0, kA, kA};
  for (int i = 0; i < 4; ++i)
    n << "  - {name: F" << names[i] << ", at: [" << xs[i] << ", 0, " << zs[i] << "]}\n"
      << "  - {name: T" << names[i] << ", at: [" << xs[i] << ", " << kH << ", " << zs[i] << "]}\n";
  n << "members:\n";
  for (int i = 0; i < 4; ++i)
    n << "  - {name: c" << names[i] << ", from: F" << names[i] << ", to: T" << names[i]
      << ", section: column, elements: 4}\n"
      << "  - {name: b" << names[i] << ", from: T" << names[i] << ", to: T" << names[(i + 1) % 4]
      << ", section: beam, elements: 2}\n";
  n << "supports:\n";
  for (int i = 0; i < 4; ++i) n << "  - {name: F" << names[i] << ", at: F" << names[i] << ", fix: clamped}\n";
  n << "masses:\n";
  for (int i = 0; i < 4; ++i) n << "  - {at: T" << names[i] << ", m: " << kM << "}\n";
  n << "analyses: [{type: modal, modes: 3}]\n";
  return d.str();
}

}  // namespace

TEST_SUITE("frame modes") {
  TEST_CASE("a one-storey 3d frame's modes are sway z, torsion about y and sway x") {
    const Study s = test::solveDeckText(shearBuilding(), "storey.yaml");
    const auto runs = test::runsOf(s);
    REQUIRE(runs.size() == 1);
    const auto* modal = resultOf<ModalResult>(runs.front()->analyses.front());
    REQUIRE(modal);
    REQUIRE(modal->modes.size() == 3);
    const double kx = 12 * kE * kIz / std::pow(kH, 3), kz = 12 * kE * kIy / std::pow(kH, 3);
    const double G = kE / (2 * (1 + kNu));
    const double twoPi = 2 * std::numbers::pi;
    const double fz = std::sqrt(kz / kM) / twoPi, fx = std::sqrt(kx / kM) / twoPi;
    const double ft =
        std::sqrt(((kx + kz) * kA * kA + 4 * G * kJ / kH) / (2 * kM * kA * kA)) / twoPi;
    for (const Mode& m : modal->modes) MESSAGE(m.frequencyHz << " Hz: " << m.description);
    // The beams' flexibility (10^-4 of the columns'), the columns' axial strain and the
    // members' mass (10^-9) are what the three-dof model leaves out: measured 7e-6, 6e-6 and
    // 1.4e-5; 1e-4 leaves a margin and tells the three apart (they differ by over 15 %).
    CHECK(modal->modes[0].frequencyHz == doctest::Approx(fz).epsilon(1e-4));
    CHECK(modal->modes[1].frequencyHz == doctest::Approx(ft).epsilon(1e-4));
    CHECK(modal->modes[2].frequencyHz == doctest::Approx(fx).epsilon(1e-4));
    // The sway modes carry all the mass along their direction, the torsion mode all the
    // roof's turning: each is named so with 100 %.
    CHECK(modal->modes[0].description == "sway uz, 100 % of the mass");
    CHECK(modal->modes[1].description == "torsion about y, 100 % of the mass");
    CHECK(modal->modes[2].description == "sway ux, 100 % of the mass");
  }

  TEST_CASE("a frame's shapes CSV and chart carry the places' coordinates and every mode") {
    const auto dir = test::scratchDir("frame-modes");
    std::ofstream(dir / "storey.yaml") << shearBuilding();
    const auto p = test::runBeamrotor(
        {"solve", (dir / "storey.yaml").string(), "--out", (dir / "out").string()});
    REQUIRE_MESSAGE(p.exitCode == 0, p.err);
    const auto rows = test::csvCells(dir / "out" / "modal_shapes.csv");
    REQUIRE(rows.size() > 1);
    const auto& header = rows.front();
    const std::size_t member = test::csvColumn(header, "member"), y = test::csvColumn(header, "y"),
                      ux = test::csvColumn(header, "mode3_ux");
    // 8 members: 4 columns of 4 elements and 4 beams of 2, each element in 4 pieces, a
    // member's first place once: 4 (4 * 4 + 1) + 4 (2 * 4 + 1) rows.
    CHECK(rows.size() - 1 == 4 * 17 + 4 * 9);
    // Sway along x: every place at the roof (y = h) moves ux = 1 (the largest, the roof
    // moving rigidly), the feet 0.
    for (std::size_t r = 1; r < rows.size(); ++r) {
      const double height = std::stod(rows[r][y]), u = std::stod(rows[r][ux]);
      if (height == kH) CHECK(std::abs(u) == doctest::Approx(1).epsilon(1e-3));
      if (height == 0) CHECK(u == 0);
    }
    CHECK(rows[1][member] == "c1");  // text bare where CSV allows (CsvTable.hpp)
    const std::string script = test::fileContents(dir / "out" / "modal_shapes.gp");
    CHECK(script.find("splot $shape3") != std::string::npos);
    CHECK(script.find("torsion about y") != std::string::npos);
    std::filesystem::remove_all(dir);
  }
}

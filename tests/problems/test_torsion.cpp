// The torsion analysis (problems/deck/torsion/TorsionKind.hpp): a shaft line's modes in twist
// against closed forms (disks on a light shaft, the uniform shaft), Holzer's residual-torque
// method on a chain of disks, and the torsional modes of the same shaft in a 3d modal analysis;
// then its composition with checks, sweeps, units, results.json, the CSV tables and bad input.
#include <doctest/doctest.h>

#include <cmath>
#include <string>
#include <vector>

#include "problems/run/RunResult.hpp"
#include "tests/Helpers.hpp"
#include "tests/problems/DeckTestSupport.hpp"
#include "tests/problems/TorsionSupport.hpp"

using namespace beamrotor;
using beamrotor::test::kPi;
using beamrotor::test::relError;
using beamrotor::test::holzerResidual;
using beamrotor::test::torsionOf;

namespace {

constexpr double kG = 80e9;  // shear modulus (Pa)

/// GJ / L of a round shaft of diameter D and length L (N m/rad).
double shaftStiffness(double D, double L) {
  return kG * kPi * std::pow(D, 4) / 32 / L;
}

/// Disks of polar inertia J[i] (kg m^2) at stations x[i] on a round steel-stiff shaft of
/// diameter D whose density is negligible (1e-6 kg/m^3: its inertia, about 1e-12 kg m^2, is
/// 1e-12 of the disks'), free in twist unless `clamped`; 3d when `threeD`.
std::string diskTrain(const std::vector<double>& J, const std::vector<double>& x, double D,
                      bool clamped, bool threeD, const std::string& analyses) {
  std::string deck = "model: {dimension: " + std::string(threeD ? "3d" : "lateral") + "}\n";
  deck += "materials:\n  - {name: light, E: 208e9, G: 80e9, rho: 1e-6}\n";
  deck += "sections:\n  - {name: shaft, shape: circle, D: " + std::to_string(D) + "}\n";
  deck += "segments:\n  - {name: shaft, length: " + std::to_string(x.back()) +
          ", section: shaft, elements: 12}\npoints:\n";
  for (std::size_t i = 0; i < x.size(); ++i)
    deck += "  - {name: p" + std::to_string(i) + ", at: " + std::to_string(x[i]) + "}\n";
  deck += "masses:\n";
  for (std::size_t i = 0; i < J.size(); ++i)
    deck += "  - {name: d" + std::to_string(i) + ", at: p" + std::to_string(i) +
            ", m: 20, Jp: " + std::to_string(J[i]) + ", Jd: 0.5}\n";
  if (clamped)
    deck += "supports:\n  - {name: root, at: start, fix: clamped}\n";
  return deck + "analyses:\n" + analyses;
}

}  // namespace

TEST_SUITE("torsion") {
  TEST_CASE("two disks on a light shaft: omega^2 = k (J1 + J2) / (J1 J2), and the free rotation") {
    const double D = 0.05, L = 1.0, J1 = 2.0, J2 = 3.0;
    const Study s = test::solveDeckText(
        diskTrain({J1, J2}, {0, L}, D, false, false, "  - {type: torsion, name: twist, modes: 2}\n"),
        "two_disks.yaml");
    const TorsionOutcome& t = torsionOf(*s.run, "twist");
    REQUIRE(t.modes.modes.size() == 2);
    CHECK(t.free);
    const double k = shaftStiffness(D, L);
    const double f = std::sqrt(k * (J1 + J2) / (J1 * J2)) / (2 * kPi);
    // The shaft's own inertia (1e-12 of the disks') and round-off: exact otherwise, as a light
    // linear element's stiffness GJ/h is exact for a shaft without span torque.
    CHECK(relError(t.modes.modes[1].frequencyHz, f) < 1e-11);
    // The rotation as one: omega^2 is round-off of K's scale, so f is at most sqrt(1e-15) of f2.
    CHECK(t.modes.modes[0].frequencyHz <= 1e-7 * f);
    // Its node sits where the disks' moments balance: x = L J2 / (J1 + J2).
    const NodalField& shape = t.modes.modes[1].shape;
    const int rx = dofIndex(Dof::rx);
    const double first = shape(t.model->node("p0"), rx), last = shape(t.model->node("p1"), rx);
    CHECK(relError(first / last, -J2 / J1) < 1e-11);
  }

  TEST_CASE("Holzer's method on a chain of four disks gives the same frequencies") {
    const std::vector<double> J{1.5, 0.4, 2.2, 0.9}, x{0, 0.3, 0.8, 1.2};
    const double D = 0.04;
    const Study s = test::solveDeckText(
        diskTrain(J, x, D, false, false, "  - {type: torsion, name: twist, modes: 4}\n"),
        "holzer.yaml");
    const TorsionOutcome& t = torsionOf(*s.run, "twist");
    REQUIRE(t.modes.modes.size() == 4);
    std::vector<double> k;
    for (std::size_t i = 0; i + 1 < x.size(); ++i) k.push_back(shaftStiffness(D, x[i + 1] - x[i]));
    for (int m = 1; m < 4; ++m) {
      const double omega = 2 * kPi * t.modes.modes[m].frequencyHz;
      const auto residual = [&](double w) { return holzerResidual(J, k, w); };
      REQUIRE(residual(omega * 0.99) * residual(omega * 1.01) < 0);
      const double root = test::bisectRoot(residual, omega * 0.99, omega * 1.01);
      CHECK(relError(omega, root) < 1e-11);
    }
  }

  TEST_CASE("a disk on a clamped shaft: omega^2 = k / J, and the 3d modal analysis agrees") {
    const double D = 0.03, L = 0.7, J = 0.8;
    const Study s = test::solveDeckText(
        diskTrain({0, J}, {0, L}, D, true, true,
                  "  - {type: torsion, name: twist, modes: 1}\n"
                  "  - {type: modal, name: all, modes: 12}\n"),
        "clamped_disk.yaml");
    const TorsionOutcome& t = torsionOf(*s.run, "twist");
    CHECK_FALSE(t.free);
    const double f = std::sqrt(shaftStiffness(D, L) / J) / (2 * kPi);
    CHECK(relError(t.modes.modes[0].frequencyHz, f) < 1e-11);
    // The 3d model's modes include the same twist (a straight round shaft's torsion decouples
    // from its bending and stretching), found by a second eigen-solve on six dofs per node.
    const ModalResult* all = resultOf<ModalResult>(s.run->analyses[1]);
    REQUIRE(all != nullptr);
    int torsional = 0;
    for (const Mode& m : all->modes)
      if (m.description.find("torsion") != std::string::npos) {
        ++torsional;
        CHECK(relError(m.frequencyHz, t.modes.modes[0].frequencyHz) < 1e-9);
      }
    CHECK(torsional == 1);
  }

  TEST_CASE("a uniform clamped shaft: f_n = (2n - 1) sqrt(G / rho) / 4L, converging as h^2") {
    // Steel, L = 2 m: f1 = 395.3 Hz. Linear elements with consistent mass converge on the
    // frequency as h^2 (the rod's element error, Cook et al., Concepts and Applications of
    // FEA, 4th ed., section 11.6); the measured ratio of errors on halving h is 4.
    const auto frequencies = [](int elements) {
      const std::string deck =
          "model: {dimension: 3d}\n"
          "materials:\n  - {name: steel, E: 208e9, G: 80e9, rho: 7850}\n"
          "sections:\n  - {name: shaft, shape: circle, D: 0.06}\n"
          "segments:\n  - {name: shaft, length: 2, section: shaft, elements: " +
          std::to_string(elements) +
          "}\n"
          "supports:\n  - {name: root, at: start, fix: clamped}\n"
          "analyses:\n  - {type: torsion, name: twist, modes: 2}\n";
      const Study s = test::solveDeckText(deck, "uniform_shaft.yaml");
      const TorsionOutcome& t = torsionOf(*s.run, "twist");
      return std::vector<double>{t.modes.modes[0].frequencyHz, t.modes.modes[1].frequencyHz};
    };
    const double c = std::sqrt(80e9 / 7850.0);
    const double f1 = c / (4 * 2.0), f2 = 3 * c / (4 * 2.0);
    const std::vector<double> coarse = frequencies(20), fine = frequencies(40);
    const double rate1 = std::log2(relError(coarse[0], f1) / relError(fine[0], f1));
    const double rate2 = std::log2(relError(coarse[1], f2) / relError(fine[1], f2));
    CHECK(rate1 == doctest::Approx(2).epsilon(0.02));
    CHECK(rate2 == doctest::Approx(2).epsilon(0.02));
    // Consistent mass overestimates (the Rayleigh quotient of an admissible shape).
    CHECK(fine[0] > f1);
    CHECK(relError(fine[0], f1) < 1e-4);
  }

  TEST_CASE("checks, sweeps and units reach the torsion analysis") {
    const double L = 1.0, J1 = 2.0, J2 = 3.0;
    std::string deck = "parameters:\n  D: 0.05\n" +
                       diskTrain({J1, J2}, {0, L}, 0.05, false, false,
                                 "  - {type: torsion, name: twist, modes: 2, shift: -4 rad^2/s^2}\n");
    deck.replace(deck.find("D: 0.050000}"), 12, "D: D}");
    deck += "checks:\n"
            "  - {name: twist, quantity: frequency 2, analysis: twist, tolerance: 1e-11,\n"
            "     reference: sqrt(80e9 * pi * D^4 / 32 / 1 * 5 / 6) / (2 * pi)}\n"
            "sweep: {parameter: D, values: [0.04, 0.05, 0.06]}\n";
    const Study s = test::solveDeckText(deck, "twist_sweep.yaml");
    REQUIRE(s.sweep);
    CHECK(test::checkAllPass(s) == 3);
    for (const RunResult* run : test::runsOf(s))
      CHECK(torsionOf(*run, "twist").modes.shift == doctest::Approx(-4).epsilon(1e-15));
    // A shift is an eigenvalue, omega^2: a length is refused at its field.
    std::string wrong = deck;
    wrong.replace(wrong.find("shift: -4 rad^2/s^2"), 19, "shift: -4 m");
    const DeckError e = test::readingError(wrong, "twist_sweep.yaml");
    CHECK(std::string(e.what()).find("shift") != std::string::npos);
  }

  TEST_CASE("the torsion analysis writes its modes to results.json and CSV, and says so") {
    const auto dir = test::scratchDir("torsion_files");
    const auto deckPath = dir / "train.yaml";
    {
      std::FILE* f = std::fopen(deckPath.c_str(), "w");
      REQUIRE(f != nullptr);
      const std::string text = diskTrain({2.0, 3.0}, {0, 1.0}, 0.05, false, false,
                                         "  - {type: torsion, name: twist, modes: 2}\n");
      std::fputs(text.c_str(), f);
      std::fclose(f);
    }
    const auto p = test::runBeamrotor({"solve", deckPath.string(), "--out", (dir / "out").string()});
    REQUIRE(p.exitCode == 0);
    CHECK(p.out.find("torsion analysis 'twist' (2 modes)") != std::string::npos);
    // The model line counts the deck's model (lateral: 4 dofs at each of 13 nodes, the 12
    // elements and the 2 masses), not the torsion analysis' own (1 dof per node).
    CHECK(p.out.find("model: lateral, 13 nodes, 14 elements, 52 dofs") != std::string::npos);
    CHECK(p.out.find("the train turning as one") != std::string::npos);
    const auto json =
        nlohmann::json::parse(test::fileContents(dir / "out" / "results.json"));
    const auto& entry = json.at("analyses").at(0);
    CHECK(entry.at("type") == "torsion");
    CHECK(entry.at("free") == true);
    const double f = std::sqrt(shaftStiffness(0.05, 1.0) * 5 / 6) / (2 * kPi);
    CHECK(relError(entry.at("frequencies_hz").at(1).get<double>(), f) < 1e-11);
    const auto rows = test::csvCells(dir / "out" / "twist_modes.csv");
    REQUIRE(rows.size() == 3);
    CHECK(relError(std::stod(rows[2][test::csvColumn(rows[0], "frequency")]), f) < 1e-11);
    CHECK(std::filesystem::exists(dir / "out" / "twist_mode_02.vtu"));
    CHECK(std::filesystem::exists(dir / "out" / "twist_shapes.csv"));
    std::filesystem::remove_all(dir);
  }

  TEST_CASE("a torsion analysis needs a shaft line") {
    const std::string frame =
        "model: {dimension: 3d}\n"
        "materials:\n  - {name: steel, E: 210e9, nu: 0.3, rho: 7850}\n"
        "sections:\n  - {name: s, shape: circle, D: 0.05}\n"
        "nodes:\n  - {name: a, at: [0, 0, 0]}\n  - {name: b, at: [0, 0, 2]}\n"
        "members:\n  - {name: post, from: a, to: b, section: s, elements: 4}\n"
        "supports:\n  - {name: base, at: a, fix: clamped}\n"
        "analyses:\n  - {type: torsion}\n";
    const DeckError e = test::readingError(frame, "frame_twist.yaml");
    const std::string message = e.what();
    INFO(message);
    CHECK(message.find("frame_twist.yaml:14") != std::string::npos);
    CHECK(message.find("shaft line") != std::string::npos);
  }
}

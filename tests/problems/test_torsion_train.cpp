// Drive trains in torsion (`train:`, problems/deck/torsion/): shafts, disks, couplings and
// gear meshes, against closed forms (two disks on a shaft; the steady response of two disks
// through a damped coupling), the classical reduction of a geared train by the ratio squared,
// and Holzer's residual-torque method as a second method on a chain of disks; then the crank
// torque's harmonics, the interference diagram, and the composition with checks, units,
// results.json, CSV and bad input.
#include <doctest/doctest.h>

#include <cmath>
#include <complex>
#include <cstdio>
#include <numbers>
#include <string>
#include <vector>

#include "problems/run/RunResult.hpp"
#include "problems/run/TorsionOutcome.hpp"
#include "problems/scenes/CrankTorque.hpp"
#include "tests/Helpers.hpp"
#include "tests/problems/DeckTestSupport.hpp"
#include "tests/problems/TorsionSupport.hpp"

using namespace beamrotor;
using beamrotor::test::kPi;
using beamrotor::test::relError;
using beamrotor::test::holzerResidual;
using beamrotor::test::torsionOf;

namespace {

constexpr double kTrainG = 80e9;  // shear modulus of the decks' materials (Pa)

std::string num(double v) {
  char buffer[40];
  std::snprintf(buffer, sizeof buffer, "%.17g", v);
  return buffer;
}

/// G J / L of a round shaft (N m/rad).
double roundShaft(double D, double L) { return kTrainG * kPi * std::pow(D, 4) / 32 / L; }

/// The materials (`light`: 1e-6 kg/m^3, whose shafts' inertia is ~1e-12 of the disks'; and
/// `steel`) and round sections of the given diameters, named s0, s1, ...
std::string header(const std::vector<double>& diameters) {
  std::string deck =
      "materials:\n  - {name: light, E: 208e9, G: 80e9, rho: 1e-6}\n"
      "  - {name: steel, E: 208e9, G: 80e9, rho: 7850}\nsections:\n";
  for (std::size_t i = 0; i < diameters.size(); ++i)
    deck += "  - {name: s" + std::to_string(i) + ", shape: circle, D: " + num(diameters[i]) +
            ", material: " + (i == 0 ? "light" : "steel") + "}\n";
  return deck;
}

/// Two disks J1 (at a.start) and J2, joined by the light shaft a (k_a) and, when kc > 0, a
/// coupling (kc, c) from a.end to b.start; J2 on b.start then, else on a.end.
std::string twoDisks(double J1, double J2, double D, double L, double kc, double c,
                     const std::string& analyses) {
  std::string deck = header({D}) + "train:\n  shafts:\n";
  deck += "    - name: a\n      segments: [{length: " + num(L) + ", section: s0, elements: 4}]\n";
  deck += "      disks: [{name: d1, at: 0, Jp: " + num(J1) + "}" +
          (kc > 0 ? "]\n" : ", {name: d2, at: " + num(L) + ", Jp: " + num(J2) + "}]\n");
  if (kc > 0) {
    deck += "    - name: b\n      segments: [{length: 0.1, section: s0, elements: 1}]\n";
    deck += "      disks: [{name: d2, at: 0, Jp: " + num(J2) + "}]\n";
    deck += "  couplings:\n    - {name: flex, from: a.end, to: b.d2, stiffness: " + num(kc) +
            " N m/rad, damping: " + num(c) + " N m s/rad}\n";
  }
  return deck + "analyses:\n" + analyses;
}

}  // namespace

TEST_SUITE("torsion train") {
  TEST_CASE("the peak of summed harmonics over a revolution: closed forms") {
    // |cos t + 0.5 sin 2t| is largest where -sin t + cos 2t = 0, sin t = 1/2: 3 sqrt(3) / 4.
    // Re(-0.5 i e^{2it}) = 0.5 sin 2t. The golden-section search ends within 1e-14 of the
    // revolution, so the peak (a maximum: error second order in the place) is round-off.
    const HarmonicPeak peakOf({1.0, 2.0});
    CHECK(relError(peakOf({{1, 0}, {0, -0.5}}), 3 * std::sqrt(3.0) / 4) < 1e-14);
    // Half orders repeat over two revolutions: with s = t/2, cos s + 0.3 sin 2s =
    // cos s (1 + 0.6 sin s) is stationary where 1.2 x^2 + x - 0.6 = 0, x = sin s.
    const double x = (-1 + std::sqrt(1 + 4 * 1.2 * 0.6)) / 2.4;
    const HarmonicPeak halfOrders({0.5, 1.0});
    CHECK(relError(halfOrders({{1, 0}, {0, -0.3}}), std::sqrt(1 - x * x) * (1 + 0.6 * x)) < 1e-14);
    // One order: the modulus, exactly.
    CHECK(HarmonicPeak({3.0})({{3, 4}}) == 5.0);
    CHECK_THROWS_AS(peakOf({{1, 0}}), std::logic_error);
  }

  TEST_CASE("two disks on a shaft: omega^2 = k (J1 + J2) / (J1 J2)") {
    const double D = 0.04, L = 0.8, J1 = 1.5, J2 = 0.4;
    const Study s = test::solveDeckText(
        twoDisks(J1, J2, D, L, 0, 0, "  - {type: torsion, name: twist, modes: 2}\n"), "two.yaml");
    const TorsionOutcome& t = torsionOf(*s.run, "twist");
    REQUIRE(t.modes.modes.size() == 2);
    const double k = roundShaft(D, L);
    const double f = std::sqrt(k * (J1 + J2) / (J1 * J2)) / (2 * kPi);
    MESSAGE("two disks: " << t.modes.modes[1].frequencyHz << " Hz, closed form " << f
                          << ", error " << relError(t.modes.modes[1].frequencyHz, f));
    // The shaft's own inertia (1e-12 of the disks') and round-off.
    CHECK(relError(t.modes.modes[1].frequencyHz, f) < 1e-9);
    CHECK(t.modes.modes[0].frequencyHz < 1e-6 * f);  // the free train turning as one
    CHECK(t.free);
  }

  TEST_CASE("a geared two-shaft train equals the train reduced by the ratio squared") {
    // Shaft a (steel, with its distributed inertia): motor J1, pinion Jg1; mesh km, ratio n;
    // shaft b: wheel Jg2, load J2. Referred to shaft a, shaft b's inertias and stiffnesses are
    // divided by n^2: a round shaft of diameter D / sqrt(n) has both (J and Ip go as D^4).
    const double n = 2.5, km = 4e5, J1 = 0.8, Jg1 = 0.05, Jg2 = 0.6, J2 = 3.0;
    const double Da = 0.05, Db = 0.09;
    const auto train = [&](bool reduced) {
      const double r = reduced ? n * n : 1;
      std::string deck = header({0.01, Da, reduced ? Db / std::sqrt(n) : Db});
      deck += "train:\n  shafts:\n"
              "    - name: a\n      segments: [{length: 0.6, section: s1, elements: 8}]\n"
              "      disks: [{name: motor, at: 0, Jp: " + num(J1) + "}, {name: pinion, at: 0.6, Jp: " +
              num(Jg1) + "}]\n"
              "    - name: b\n      segments: [{length: 0.9, section: s2, elements: 8}]\n"
              "      disks: [{name: wheel, at: 0, Jp: " + num(Jg2 / r) + "}, {name: load, at: 0.9, Jp: " +
              num(J2 / r) + "}]\n";
      deck += reduced ? "  couplings:\n    - {name: mesh, from: a.pinion, to: b.wheel, stiffness: " +
                            num(km) + "}\n"
                      : "  gears:\n    - {name: mesh, from: a.pinion, to: b.wheel, ratio: " + num(n) +
                            ", stiffness: " + num(km) + "}\n";
      return deck + "analyses:\n  - {type: torsion, name: twist, modes: 5}\n";
    };
    const Study geared = test::solveDeckText(train(false), "geared.yaml");
    const Study reduced = test::solveDeckText(train(true), "reduced.yaml");
    const auto& g = torsionOf(*geared.run, "twist").modes.modes;
    const auto& r = torsionOf(*reduced.run, "twist").modes.modes;
    REQUIRE(g.size() == 5);
    REQUIRE(r.size() == 5);
    double worst = 0;
    for (int m = 1; m < 5; ++m) worst = std::max(worst, relError(g[m].frequencyHz, r[m].frequencyHz));
    MESSAGE("geared against reduced: largest relative difference " << worst << " over modes 2-5 ("
                                                                   << g[1].frequencyHz << " Hz ...)");
    // The same eigenproblem in other coordinates (theta_b = theta_b' / n): round-off of the
    // Lanczos solves of two matrices of condition ~1e6.
    CHECK(worst < 1e-9);
    // The wheel's twist in its own coordinates is the reduced one's over n.
    CHECK(torsionOf(*geared.run, "twist").speedRatios[1] == doctest::Approx(1 / n).epsilon(1e-15));
  }

  TEST_CASE("Holzer's method: the residual torque vanishes at every natural frequency") {
    // A chain J0 -k0- J1 -kc- J2 -k1- J3 of disks on two light shafts and a coupling.
    const std::vector<double> J{1.2, 0.3, 0.5, 2.0};
    const double D = 0.03, La = 0.5, Lb = 0.7, kc = 6e3;
    std::string deck = header({D}) + "train:\n  shafts:\n";
    deck += "    - name: a\n      segments: [{length: " + num(La) + ", section: s0, elements: 3}]\n"
            "      disks: [{name: j0, at: 0, Jp: " + num(J[0]) + "}, {name: j1, at: " + num(La) +
            ", Jp: " + num(J[1]) + "}]\n";
    deck += "    - name: b\n      segments: [{length: " + num(Lb) + ", section: s0, elements: 3}]\n"
            "      disks: [{name: j2, at: 0, Jp: " + num(J[2]) + "}, {name: j3, at: " + num(Lb) +
            ", Jp: " + num(J[3]) + "}]\n";
    deck += "  couplings:\n    - {name: c, from: a.j1, to: b.j2, stiffness: " + num(kc) + "}\n";
    deck += "analyses:\n  - {type: torsion, name: twist, modes: 4}\n";
    const Study s = test::solveDeckText(deck, "holzer.yaml");
    const auto& modes = torsionOf(*s.run, "twist").modes.modes;
    REQUIRE(modes.size() == 4);
    const std::vector<double> k{roundShaft(D, La), kc, roundShaft(D, Lb)};
    for (int m = 1; m < 4; ++m) {
      const double w = 2 * kPi * modes[m].frequencyHz;
      // Relative to the largest inertia torque at w; the light shafts' inertia (1e-12) and
      // the eigenvalue's round-off.
      const double residual = holzerResidual(J, k, w) / (J[3] * w * w);
      // Holzer's residual changes sign across the root: a root of the chain's own equation.
      const double below = holzerResidual(J, k, w * (1 - 1e-6)), above = holzerResidual(J, k, w * (1 + 1e-6));
      MESSAGE("mode " << m + 1 << ": " << modes[m].frequencyHz << " Hz, Holzer residual " << residual);
      CHECK(std::abs(residual) < 1e-8);
      CHECK(below * above < 0);
    }
  }

  TEST_CASE("steady response of two disks through a damped coupling: the closed form") {
    // J1 -k_a- (a.end, massless) -(kc + i w c)- J2: the shaft and the coupling in series make
    // k = k_a z / (k_a + z), z = kc + i w c. A torque T cos(w t) on J1 gives the torque in
    // both T k J2 / (w^2 J1 J2 - k (J1 + J2)).
    const double J1 = 1.0, J2 = 0.5, D = 0.04, L = 0.5, kc = 2e4, c = 15, T = 100;
    const double rpm = 1800, order = 2;
    const std::string torques = "  - {type: torsion, name: twist, modes: 3, speed: " + num(rpm) +
                                " rpm,\n     torques: [{at: a.d1, order: " + num(order) +
                                ", amplitude: " + num(T) + " N m, phase: 30 deg}]}\n";
    const Study s = test::solveDeckText(twoDisks(J1, J2, D, L, kc, c, torques), "forced.yaml");
    const TorsionOutcome& t = torsionOf(*s.run, "twist");
    REQUIRE(t.atSpeed);
    const double w = order * rpm * 2 * kPi / 60;
    const std::complex<double> z(kc, w * c), ka = roundShaft(D, L);
    const std::complex<double> k = ka * z / (ka + z);
    const double closed = std::abs(T * k * J2 / (w * w * J1 * J2 - k * (J1 + J2)));
    for (const char* name : {"flex", "a"}) {
      const double computed = measureTorsion("torque", name, t);
      MESSAGE(name << ": " << computed << " N m, closed form " << closed << ", error "
                   << relError(computed, closed));
      // The light shafts' inertia (1e-12) and round-off.
      CHECK(relError(computed, closed) < 1e-9);
    }
    // The twist of J2: theta2 = k theta1 / (k - w^2 J2), theta1 from the first equation.
    const std::complex<double> theta1 =
        T * (k - w * w * J2) / ((k - w * w * J1) * (k - w * w * J2) - k * k);
    const double twist2 = std::abs(k * theta1 / (k - w * w * J2));
    CHECK(relError(measureTorsion("twist", "b.d2", t), twist2) < 1e-9);
  }

  TEST_CASE("crank torque: the triplex's harmonics are multiples of 3, its mean the pumping work") {
    const crank::Geometry g = crank::makeGeometry(0.0188, 0.288);
    const double omega = 588 * 2 * kPi / 60, pA = 32e6 * kPi * 0.045 * 0.045 / 4;
    const crank::TorqueSeries series = crank::crankTorqueSeries(
        g, {17.79, 0.93, pA}, {0, 2 * kPi / 3, 4 * kPi / 3}, omega, 12);
    // The work p A 2r per stroke, three strokes a revolution: 3 p A r / pi (the inertia terms
    // store and return energy). Trapezoidal rule on 2^14 samples over a kinked periodic
    // integrand: error ~ (2 pi / 2^14)^2 relative.
    const double mean = 3 * pA * g.r / kPi;
    MESSAGE("mean crank torque " << series.mean << " N m, 3 p A r / pi = " << mean);
    CHECK(relError(series.mean, mean) < 1e-6);
    double order3 = 0;
    for (const auto& h : series.harmonics) {
      // Three cranks at 120 deg cancel these orders; what remains is the trapezoidal rule's
      // error on the kinked integrand (measured 1.1e-8 of the mean).
      if (h.order % 3 != 0) CHECK(h.amplitude < 1e-7 * mean);
      if (h.order == 3) order3 = h.amplitude;
    }
    CHECK(order3 > 1e-3 * mean);  // the triplex's ripple: 24.2 N m, 2.6 % of the mean
    // One crank without pressure: the reciprocating mass's torque m a v / omega has the mean 0.
    const crank::TorqueSeries inertia = crank::crankTorqueSeries(g, {17.79, 0, 0}, {0}, omega, 4);
    CHECK(std::abs(inertia.mean) < 1e-9 * inertia.harmonics[1].amplitude);
  }

  TEST_CASE("interference crossings at order x speed = frequency; checks, sweeps, files") {
    const double J1 = 1.0, J2 = 0.5, D = 0.04, L = 0.5, kc = 2e4, c = 15;
    const std::string analysis =
        "  - {type: torsion, name: twist, modes: 3, speed: 1800 rpm, orders: [1, 2, 4],\n"
        "     speeds: {from: 100 rpm, to: 3000 rpm, steps: 20},\n"
        "     torques: [{at: a.d1, order: 2, amplitude: 100 N m}]}\n";
    std::string deck = "parameters:\n  c: " + num(c) + " N m s/rad\n" +
                       twoDisks(J1, J2, D, L, kc, c, analysis);
    deck.replace(deck.find("damping: " + num(c) + " N m s/rad"), 9 + num(c).size() + 10,
                 "damping: c");
    // The closed form of the previous case, written in the deck as a check's reference.
    const double w = 2 * 1800 * 2 * kPi / 60;
    const std::complex<double> ka = roundShaft(D, L);
    const auto closed = [&](double damping) {
      const std::complex<double> z(kc, w * damping), keff = ka * z / (ka + z);
      return std::abs(100.0 * keff * J2 / (w * w * J1 * J2 - keff * (J1 + J2)));
    };
    deck += "checks:\n  - {name: coupling torque, quantity: torsion torque flex, analysis: twist,\n"
            "     reference: " + num(closed(c)) + " N m, tolerance: 1e-9,\n     when: c / (1 N m s/rad) == " + num(c) + "}\n"
            "sweep: {parameter: c, values: [5, " + num(c) + ", 40]}\n";
    const Study s = test::solveDeckText(deck, "crossings.yaml");
    REQUIRE(s.sweep);
    CHECK(test::checkAllPass(s) == 1);
    const std::vector<double> dampings{5, c, 40};
    const auto runs = test::runsOf(s);
    REQUIRE(runs.size() == 3);
    for (std::size_t i = 0; i < runs.size(); ++i)
      CHECK(relError(measureTorsion("torque", "flex", torsionOf(*runs[i], "twist")), closed(dampings[i])) < 1e-9);
    const TorsionOutcome& t = torsionOf(*runs[1], "twist");
    // Every crossing lies where order x speed / 60 equals the mode's frequency, within range.
    REQUIRE(!t.crossings.empty());
    for (const TorsionCrossing& x : t.crossings) {
      CHECK(relError(x.order * x.speed / (2 * kPi), t.modes.modes[x.mode - 1].frequencyHz) < 1e-14);
      CHECK(x.speed >= 100 * 2 * kPi / 60);
      CHECK(x.speed <= 3000 * 2 * kPi / 60);
    }
    CHECK(t.sweep.size() == 21);
  }

  TEST_CASE("a train's results reach results.json, CSV and the summary") {
    const auto dir = test::scratchDir("torsion_train_files");
    const auto deckPath = dir / "train.yaml";
    {
      std::FILE* f = std::fopen(deckPath.c_str(), "w");
      REQUIRE(f != nullptr);
      const std::string text = twoDisks(
          1.0, 0.5, 0.04, 0.5, 2e4, 15,
          "  - {type: torsion, name: twist, modes: 3, speed: 1800 rpm, orders: [2],\n"
          "     speeds: {from: 100 rpm, to: 3000 rpm, steps: 20},\n"
          "     torques: [{at: a.d1, order: 2, amplitude: 100 N m}]}\n");
      std::fputs(text.c_str(), f);
      std::fclose(f);
    }
    const auto p = test::runBeamrotor({"solve", deckPath.string(), "--out", (dir / "out").string()});
    INFO(p.out << p.err);
    REQUIRE(p.exitCode == 0);
    CHECK(p.out.find("steady response at 1800 rpm") != std::string::npos);
    CHECK(p.out.find("torque flex:") != std::string::npos);
    CHECK(p.out.find("order 2 x mode 2") != std::string::npos);
    const auto json = nlohmann::json::parse(test::fileContents(dir / "out" / "results.json"));
    const auto& train = json.at("analyses").at(0).at("train");
    CHECK(train.at("reference") == "a");
    CHECK(train.at("interference").at("crossings").size() == 1);
    CHECK(train.at("response").at("torques_n_m").at("flex").at("peak").get<double>() > 0);
    for (const char* file : {"twist_interference.csv", "twist_crossings.csv", "twist_torques.csv",
                             "twist_response.csv"})
      CHECK(std::filesystem::exists(dir / "out" / file));
    const auto rows = test::csvCells(dir / "out" / "twist_response.csv");
    CHECK(rows.size() == 1 + 21);  // the names and 21 speeds
    std::filesystem::remove_all(dir);
  }

  TEST_CASE("bad train input names the file, line and field") {
    const std::string good = twoDisks(1.0, 0.5, 0.04, 0.5, 2e4, 15,
                                      "  - {type: torsion, name: twist, speed: 1800 rpm,\n"
                                      "     torques: [{at: a.d1, order: 2, amplitude: 100 N m}]}\n");
    const auto refused = [&](const std::string& from, const std::string& to, const std::string& says) {
      std::string deck = good;
      REQUIRE(deck.find(from) != std::string::npos);
      deck.replace(deck.find(from), from.size(), to);
      const DeckError e = test::readingError(deck, "bad_train.yaml");
      INFO(e.what());
      CHECK(std::string(e.what()).find("bad_train.yaml:") != std::string::npos);
      CHECK(std::string(e.what()).find(says) != std::string::npos);
    };
    refused("to: b.d2", "to: b.d3", "no station 'b.d3'");
    refused("at: a.d1, order", "at: a.d9, order", "did you mean");
    refused("amplitude: 100 N m", "amplitude: 100 N", "amplitude");
    refused("stiffness: 20000 N m/rad", "stiffness: 20000 N/m", "stiffness");
    refused("speed: 1800 rpm,", "", "speed");
    refused("name: b\n", "name: b\n      stations: [{name: far, at: 5}]\n", "beyond the shaft's end");
  }
}

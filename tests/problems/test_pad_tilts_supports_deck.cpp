// The rotor analyses that put supports of their own in place of the bearings, on a deck whose
// tilting-pad bearing keeps its pads' tilts as dofs (`pad_tilts: dofs`): the critical-speed
// map (a swept stiffness), bearing-loads (pinned, or the bearings' synchronous stiffness) and
// level1-stability's critical speed ratio (pinned) take the pads condensed, so their answers
// equal the `pad_tilts: condensed` deck's to the bit; level1-stability's Q0 is the full
// model's (tests/fem/rotor/test_level_one_pad_tilts.cpp checks it against a closed form).
// The pads' own modes as a check quantity and a study output (`pad_mode N PROPERTY`).
#include <doctest/doctest.h>

#include <cmath>
#include <fstream>
#include <numbers>
#include <sstream>
#include <string>

#include "problems/run/Study.hpp"
#include "problems/study/DesignStudyRun.hpp"
#include "tests/problems/DeckTestSupport.hpp"
#include "tests/problems/TiltingPadShaftDeck.hpp"

using namespace beamrotor;
using namespace beamrotor::test;

namespace {

Study solvePadSupportsDeck(const std::string& choice) {
  return solveDeckText(
      tiltingPadShaftDeck("pads and supports", choice) + R"(
analyses:
  - {type: critical-speed-map, name: map, from_k: 1e7, to_k: 1e10, points: 5, critical_speeds: 2}
  - {type: bearing-loads, name: pinned}
  - {type: bearing-loads, name: elastic, bearings: elastic, speed_rpm: 4500}
  - type: level1-stability
    name: level1
    speed_rpm: 4500
    modes: 4
    stages: [{power: 300 kW, diameter: 300 mm, tip_width: 15 mm, discharge_density: 20 kg/m^3,
              suction_density: 10 kg/m^3}]
)",
      "pads.yaml");
}

}  // namespace

TEST_CASE("pad tilts as dofs: the map, the bearing loads and the CSR equal the condensed deck's") {
  const Study dofs = solvePadSupportsDeck(", pad_tilts: dofs");
  const Study condensed = solvePadSupportsDeck("");
  REQUIRE(dofs.run);
  REQUIRE(condensed.run);
  const auto& a = dofs.run->analyses;
  const auto& b = condensed.run->analyses;
  // The same model under the analysis's own supports: the same numbers, bit for bit.
  const CriticalSpeedMap& ma = resultOf<CriticalSpeedMapOutcome>(a.at(0))->map;
  const CriticalSpeedMap& mb = resultOf<CriticalSpeedMapOutcome>(b.at(0))->map;
  CHECK(ma.speeds == mb.speeds);
  CHECK(ma.pinned == mb.pinned);
  CHECK(ma.freeFree == mb.freeFree);
  for (int k : {1, 2}) {
    const GravityLoads& la = resultOf<BearingLoadsOutcome>(a.at(std::size_t(k)))->loads;
    const GravityLoads& lb = resultOf<BearingLoadsOutcome>(b.at(std::size_t(k)))->loads;
    REQUIRE(la.bearings.size() == 2);
    REQUIRE(lb.bearings.size() == 2);
    for (std::size_t i = 0; i < 2; ++i) {
      CHECK(la.bearings[i].fy == lb.bearings[i].fy);
      CHECK(la.bearings[i].fz == lb.bearings[i].fz);
    }
    CHECK(la.uy == lb.uy);
  }
  const LevelOneResult& qa = resultOf<LevelOneOutcome>(a.at(3))->screening;
  const LevelOneResult& qb = resultOf<LevelOneOutcome>(b.at(3))->screening;
  CHECK(qa.map.rigidCriticalSpeed == qb.map.rigidCriticalSpeed);
  CHECK(qa.map.ratio == qb.map.ratio);
  CHECK(qa.anticipated == qb.anticipated);
  // Q0 is each model's own: the full model's differs from the synchronous condensation's
  // (the threshold whirl is not the spin speed here). Both found, the pads' relaxations not
  // the least damped.
  REQUIRE(qa.found);
  REQUIRE(qb.found);
  CHECK_FALSE(qa.bearingModeAtQ0);
  MESSAGE("Q0 dofs ", qa.zeroDecrement, " condensed ", qb.zeroDecrement, " f ",
          qa.frequencyHzAtQ0, " ", qb.frequencyHzAtQ0);
}

namespace {

/// The shaft deck with its pads' tilts as dofs of inertia `Ip` (a parameter) and a rotor
/// analysis; `checks` appended.
std::string padModeShaftDeck(const std::string& checks) {
  std::string text = tiltingPadShaftDeck("pad modes", ", pad_tilts: {inertia: Ip}");
  text += "parameters: {Ip: 0.02 kg*m^2}\n";
  text += "analyses: [{type: rotor, name: r, speed_rpm: 4500, modes: 2}]\n";
  text += checks;
  return text;
}

}  // namespace

TEST_CASE("pad tilts as dofs: pad_mode N PROPERTY in a check and a study output") {
  const Study first = solveDeckText(padModeShaftDeck(""), "pads.yaml");
  REQUIRE(first.run);
  const RotorModesResult& r = *resultOf<RotorModesResult>(first.run->analyses.at(0));
  REQUIRE_FALSE(r.bearingModes.empty());
  const RotorMode& pad = r.bearingModes.front();
  CAPTURE(pad.eigenvalue);
  // With the pads' inertia their first mode here oscillates (a pair): every property is finite.
  REQUIRE(pad.eigenvalue.imag() > 0);
  // The check reads the same mode the analysis reports: its properties against the eigenvalue
  // (Hz = Im / 2 pi, decay = -Re, zeta = -Re / |lambda|, delta = -2 pi Re / Im), to round-off.
  const double two_pi = 2 * std::numbers::pi;
  const auto text = [](double v) {
    std::ostringstream s;
    s.precision(17);
    s << v;
    return s.str();
  };
  const std::string checks =
      "checks:\n"
      "  - {name: f, quantity: pad_mode 1 frequency, reference: " +
      text(pad.eigenvalue.imag() / two_pi) + " Hz, tolerance: 1e-12}\n" +
      "  - {name: decay, quantity: pad_mode 1 decay_rate, reference: " +
      text(-pad.eigenvalue.real()) + ", tolerance: 1e-12}\n" +
      "  - {name: zeta, quantity: pad_mode 1 damping_ratio, reference: " +
      text(-pad.eigenvalue.real() / std::abs(pad.eigenvalue)) + ", tolerance: 1e-12}\n" +
      "  - {name: delta, quantity: pad_mode 1 log_decrement, reference: " +
      text(-two_pi * pad.eigenvalue.real() / pad.eigenvalue.imag()) + ", tolerance: 1e-12}\n" +
      "  - {name: energy, quantity: pad_mode 1 bearing_energy, reference: " +
      text(pad.bearingEnergy) + ", tolerance: 1e-12}\n";
  const Study checked = solveDeckText(padModeShaftDeck(checks), "pads.yaml");
  REQUIRE(checked.run);
  CHECK(checkAllPass(checked) == 5);
  // A pad mode past those found, and a deck without pad dofs, are refused.
  const DeckError none = readingError(
      tiltingPadShaftDeck("no pads", "") +
          "analyses: [{type: rotor, name: r, speed_rpm: 4500, modes: 2}]\n"
          "checks: [{name: p, quantity: pad_mode 1 frequency, reference: 1, tolerance: 1}]\n",
      "pads.yaml");
  CHECK(none.message().find("pad_tilts: dofs") != std::string::npos);
  const DeckError property = readingError(
      padModeShaftDeck("checks: [{name: p, quantity: pad_mode 1 whirl, reference: 1, tolerance: 1}]\n"),
      "pads.yaml");
  CHECK(property.message().find("decay_rate") != std::string::npos);

  // A study over the pads' inertia: its column equals each point's own solve.
  const auto scratch = scratchDir("pad-mode-study");
  const auto deck = scratch / "pads.yaml";
  {
    std::ofstream out(deck);
    out << padModeShaftDeck("");
  }
  DesignStudyRequest request;
  request.deckPath = deck.string();
  request.outDir = (scratch / "out").string();
  request.study.sweeps = {"Ip=0.01:0.03:2"};
  request.study.outputs = {"pad_mode 1 frequency", "pad_mode 1 decay_rate"};
  const DesignStudyOutcome study = runDesignStudy(request);
  CHECK(study.failed == 0);
  const auto rows = csvCells(study.dir / "study.csv");
  REQUIRE(rows.size() == 4);
  const auto& h = rows[0];
  for (std::size_t i = 1; i < rows.size(); ++i) {
    const std::string ip = rows[i][csvColumn(h, "Ip")];
    const Study point = solveDeckText(
        padModeShaftDeck("").replace(padModeShaftDeck("").find("Ip: 0.02 kg*m^2"), 15, "Ip: " + ip), "pads.yaml");
    const RotorMode& m = resultOf<RotorModesResult>(point.run->analyses.at(0))->bearingModes.at(0);
    CAPTURE(ip);
    // The study prints 17 significant digits: the same double.
    CHECK(std::stod(rows[i][csvColumn(h, "pad_mode 1 frequency")]) == m.dampedFrequencyHz);
    CHECK(std::stod(rows[i][csvColumn(h, "pad_mode 1 decay_rate")]) == -m.eigenvalue.real());
  }
}

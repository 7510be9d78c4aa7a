// Tilting-pad journal bearings through a deck (type: tilting-pad): the reader's units, pads and
// load reach elements/TiltingPadBearing, and its operating points reach the Campbell outcome
// the outputs write.
//  - the shipped deck (problems/compressor_rotor_tilting_pads.yaml): each bearing's operating
//    point against a direct solve at its weight share (the rotor's mass over two, a closed form
//    of the deck's geometry), every mode stable over the range;
//  - bad pads named at their field.
#include <doctest/doctest.h>

#include <algorithm>
#include <cmath>
#include <numbers>
#include <sstream>
#include <string>
#include <vector>

#include "elements/TiltingPadBearing.hpp"
#include "problems/cli/RotorSummary.hpp"
#include "problems/run/Study.hpp"
#include "tests/Helpers.hpp"
#include "tests/elements/TiltingPadTestSupport.hpp"
#include "tests/fem/rotor/RotorTestSupport.hpp"
#include "tests/problems/DeckTestSupport.hpp"
#include "tests/problems/TiltingPadShaftDeck.hpp"

using namespace beamrotor;
using namespace beamrotor::test;

TEST_SUITE("slow") {
  TEST_CASE("tilting-pad deck: the shipped compressor on four pads") {
    const Study s = solveShippedDeck("compressor_rotor_tilting_pads.yaml");
    CHECK(checkAllPass(s) == 1);
    const CampbellOutcome& c = *resultOf<CampbellOutcome>(s.run->analyses.at(2));
    REQUIRE(c.journals.size() == 2);
    const double mass = compressorRotorMass();
    const TiltingPads pads = fourPadsBetween();  // the deck's pads
    for (const JournalBearingCurve& j : c.journals) {
      // The symmetric rotor's half, to the static solve's round-off.
      CHECK(j.journal.load == doctest::Approx(mass * 9.81 / 2).epsilon(1e-9));
      for (std::size_t i : {std::size_t(0), j.speeds.size() / 2, j.speeds.size() - 1}) {
        // The deck's Newton starts from the last speed's equilibrium, the direct one from the
        // centre: both stop within 1e-11 of the load, which moves the journal by about that
        // much of its eccentricity (and the coefficients alike); 1e-10 keeps a margin.
        const TiltingPadPoint direct = tiltingPadPoint(j.journal, pads, j.speeds[i], {24, 8});
        CHECK(j.eccentricity[i] == doctest::Approx(direct.eccentricity).epsilon(1e-10));
        CHECK(j.coefficients[i].kyy == doctest::Approx(direct.synchronous.kyy).epsilon(1e-10));
        CHECK(j.coefficients[i].czz == doctest::Approx(direct.synchronous.czz).epsilon(1e-10));
        // Four pads with the load between two: isotropic (tests/elements/...).
        CHECK(j.coefficients[i].kzz == doctest::Approx(j.coefficients[i].kyy).epsilon(1e-8));
      }
    }
    // No cross-coupling to drive a forward whirl: every mode decays over the whole range.
    CHECK_FALSE(c.onset.has_value());
    // The four-pad symmetry makes the cross-coupled stiffness vanish; the film's sums leave
    // round-off of the direct stiffness (5e-8 beside 3e7 N/m), which the summary shows as 0,
    // in any units.
    for (const JournalBearingCurve& j : c.journals)
      for (const BearingCoefficients& k : j.coefficients) {
        CHECK(std::abs(k.kyz) <= 1e-12 * k.kyy);
        CHECK(std::abs(k.kzy) <= 1e-12 * k.kyy);
      }
    for (const OutputUnits& units : {OutputUnits{}, parseOutputUnits("force=kN")}) {
      std::ostringstream summary;
      cli::printRotor(summary, s.run->analyses.at(2), c, units);
      CAPTURE(summary.str());
      const std::string text = summary.str();
      std::size_t lines = 0;
      for (std::size_t at = text.find("(tilting-pad) at"); at != std::string::npos;
           at = text.find("(tilting-pad) at", at + 1), ++lines)
        CHECK(text.substr(at, text.find('\n', at) - at).find(", kxy 0, kyx 0 ") !=
              std::string::npos);
      CHECK(lines == 4);  // both bearings at both ends of the sweep
    }
  }
}

TEST_SUITE("rotor decks") {
  TEST_CASE("tilting-pad deck: bad pads are named") {
    auto deckWith = [](const std::string& bearing) {
      return std::string(R"(
title: a tilting-pad bearing
model: {dimension: lateral}
materials: [{name: steel, E: 2.1e11, nu: 0.3, rho: 7850}]
sections: [{name: shaft, shape: circle, D: 100 mm}]
segments: [{name: shaft, length: 0.2, section: shaft, elements: 2}]
bearings:
  - {name: A, at: start, type: tilting-pad, D: 100 mm, L: 50 mm, c: 100 um, mu: 0.02 Pa s,
     from_rpm: 3000, to_rpm: 6000, steps: 1, )") +
             bearing + "}\n  - {name: B, at: end, kxx: 1e8, kyy: 1e8}\n";
    };
    // The field's line; a missing key is named at the bearing's entry (line 8).
    auto messageOf = [&](const std::string& bearing, int line = 9) {
      const DeckError e = readingError(deckWith(bearing), "pads.yaml");
      CHECK(e.place().line == line);
      return e.message();
    };
    const std::string good = "load: 5000 N, arc: 80 deg, preload: 0.3, ";
    CHECK(messageOf(good + "pads: 5, orientation: load-on-pad")
              .find("5 pads of 80 deg do not fit around the journal") != std::string::npos);
    CHECK(messageOf(good + "pads: 4, orientation: on-pad").find("load-on-pad") !=
          std::string::npos);
    CHECK(messageOf(good + "pads: 4, orientation: load-on-pad, offset: 0.9")
              .find("the pivot offset") != std::string::npos);
    CHECK(messageOf("load: 5000 N, arc: 80 deg, pads: 4, orientation: load-on-pad", 8)
              .find("preload") != std::string::npos);
    CHECK(messageOf(good + "pads: 4, orientation: load-on-pad, model: finite")
              .find("unknown key") != std::string::npos);
    CHECK(messageOf("load: 0, arc: 80 deg, preload: 0.3, pads: 4, orientation: load-on-pad")
              .find("solved for a load") != std::string::npos);
    // A load the pads carry only on a film thinner than 1 % of c.
    CHECK(messageOf("load: 1e8 N, arc: 80 deg, preload: 0.3, pads: 4, orientation: load-on-pad")
              .find("1 % of the clearance") != std::string::npos);
    // A good one reads and runs.
    const Study s = solveDeckText(deckWith("load: 5000 N, arc: 60 deg, preload: 0.3, pads: 5, "
                                           "orientation: load-on-pad, offset: 0.6") +
                                      "analyses: [{type: campbell, name: c, modes: 2, "
                                      "from_rpm: 3000, to_rpm: 6000, steps: 1}]\n",
                                  "pads.yaml");
    REQUIRE(s.run);
  }

  TEST_CASE("tilting-pad deck: the pads' tilts as dofs") {
    auto deckWith = [](const std::string& choice, const std::string& analysis = "") {
      return tiltingPadShaftDeck("tilting pads as dofs", choice) +
             "analyses: [{type: rotor, name: r, speed_rpm: 3000, modes: 2}" + analysis + "]\n";
    };
    // At a table speed the full model is exact; where the per-mode iteration settles it lands
    // on the full model's eigenvalues (tests/fem/rotor/test_whirl_dependent_bearings.cpp): the
    // two agree to the iteration's tolerance (1e-10 of lambda), 1e-8 with a margin.
    const Study each = solveDeckText(deckWith(", whirl_coefficients: each-mode"), "pads.yaml");
    const Study dofs = solveDeckText(deckWith(", pad_tilts: dofs"), "pads.yaml");
    const Study heavy =
        solveDeckText(deckWith(", pad_tilts: {inertia: 20000 kg*mm^2}"), "pads.yaml");
    const RotorModesResult& a = *resultOf<RotorModesResult>(each.run->analyses.at(0));
    const RotorModesResult& b = *resultOf<RotorModesResult>(dofs.run->analyses.at(0));
    const RotorModesResult& h = *resultOf<RotorModesResult>(heavy.run->analyses.at(0));
    REQUIRE(b.modes.size() == 2);
    CHECK_FALSE(b.coefficients.atOwnWhirl);
    std::vector<RotorMode> full = b.modes;  // the rotor's modes and the pads'
    full.insert(full.end(), b.bearingModes.begin(), b.bearingModes.end());
    int settled = 0;
    for (const RotorMode& m : a.modes) {
      if (m.whirlIterations == 0) continue;
      bool named = false;  // left at its synchronous eigenvalue, named in a warning
      for (const auto& u : a.coefficients.unsettled)
        named = named || std::abs(u.frequencyHz - m.dampedFrequencyHz) < 1e-12;
      if (named) continue;
      CAPTURE(m.eigenvalue);
      double nearest = 1e300;
      for (const RotorMode& f : full) nearest = std::min(nearest, std::abs(f.eigenvalue - m.eigenvalue));
      CHECK(nearest <= 1e-8 * std::abs(m.eigenvalue));
      ++settled;
    }
    CHECK(settled >= 1);
    // 0.02 kg m^2 pads move the modes (measured below 1e-3 relative).
    REQUIRE(h.modes.size() == 2);
    CHECK(std::abs(h.modes[0].eigenvalue - b.modes[0].eigenvalue) > 0);
    CHECK_FALSE(b.bearingModes.empty());
    for (const RotorMode& m : b.bearingModes) CHECK(std::string(energyIn(m)) == "pads");
    // Refused where the pads cannot be dofs, named at the field.
    const DeckError both =
        readingError(deckWith(", whirl_coefficients: each-mode, pad_tilts: dofs"), "pads.yaml");
    CHECK(both.place().line == 10);
    CHECK(both.message().find("each-mode") != std::string::npos);
    const DeckError bad = readingError(deckWith(", pad_tilts: full"), "pads.yaml");
    CHECK(bad.place().line == 10);
    CHECK(bad.message().find("condensed") != std::string::npos);
  }
}

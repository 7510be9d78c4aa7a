// Finite-length plain journal bearings through a deck (model: finite): the reader's units, the
// table speeds and the load reach the film solver, and its operating points reach the
// Campbell outcome the outputs write.
//  - Raimondi and Boyd (1958), L/D = 1: at the speed where S = 0.121 the journal runs at
//    eps = 0.6 (their table), through the deck;
//  - oil whip of a rigid rotor on two L/D 1.5 bearings: the Campbell analysis' onset against
//    the stability threshold written from the deck's own coefficient table (a second method:
//    Lund's threshold mass instead of the eigensolver);
//  - the shipped deck on L/D 1.2 bearings (problems/compressor_rotor_long_bearings.yaml):
//    each bearing's operating point against a direct solve at its weight share (the
//    rotor's mass over two, a closed form of the deck's geometry), and the run completes.
#include <doctest/doctest.h>

#include <cmath>
#include <sstream>
#include <string>

#include "elements/FiniteJournalBearing.hpp"
#include "problems/cli/RotorSummary.hpp"
#include "problems/cli/Summary.hpp"
#include "problems/run/Study.hpp"
#include "tests/Helpers.hpp"
#include "tests/fem/rotor/RotorTestSupport.hpp"
#include "tests/problems/DeckTestSupport.hpp"

using namespace beamrotor;
using namespace beamrotor::test;

namespace {

// S = mu N L D / W (R / c)^2 = 0.02 * 50 * 0.1 * 0.1 / W * 500^2 = 2500 N / W at 3000 rpm.
const char* kRaimondiBoydDeck = R"(
title: one journal at Raimondi and Boyd's eps = 0.6 (L/D = 1)
model: {dimension: lateral}
materials: [{name: steel, E: 2.1e11, nu: 0.3, rho: 7850}]
sections: [{name: shaft, shape: circle, D: 100 mm}]
segments: [{name: shaft, length: 0.2, section: shaft, elements: 2}]
bearings:
  - {name: A, at: start, type: plain-journal, D: 100 mm, L: 100 mm, c: 100 um, mu: 0.02 Pa s,
     load: 2500 N / 0.121, from_rpm: 3000, to_rpm: 6000, steps: 1, model: finite,
     grid: {circumferential: 288, axial: 36}}
  - {name: B, at: end, kxx: 1e8, kyy: 1e8}
analyses:
  - {type: campbell, name: campbell, modes: 2, from_rpm: 3000, to_rpm: 6000, steps: 1}
)";

// A stiff steel shaft (E 1000 times steel's: bending stiffness 6e12 N/m against the film's
// 1e8) of 12.3 kg with 500 kg at its middle on two equal bearings: its cylindrical whirl is
// half the rotor's mass on one bearing.
const char* kRigidRotorDeck = R"(
title: rigid rotor on two long plain journal bearings
model: {dimension: lateral, rotary_inertia: true}
materials: [{name: stiff, E: 2.1e14, nu: 0.3, rho: 7850}]
sections: [{name: shaft, shape: circle, D: 100 mm}]
segments: [{name: shaft, length: 0.2, section: shaft, elements: 2}]
points: [{name: mid, at: 0.1}]
masses: [{name: rotor, at: mid, m: 500 kg}]
bearings:
  - {name: A, at: start, type: plain-journal, D: 50 mm, L: 75 mm, c: 50 um, mu: 0.01 Pa s,
     load: 2452.5 N, from_rpm: 2000, to_rpm: 20000, steps: 18}
  - {name: B, at: end, type: plain-journal, D: 50 mm, L: 75 mm, c: 50 um, mu: 0.01 Pa s,
     load: 2452.5 N, from_rpm: 2000, to_rpm: 20000, steps: 18}
analyses:
  - {type: campbell, name: campbell, modes: 4, from_rpm: 2000, to_rpm: 20000, steps: 18}
)";

/// The table's coefficients at Omega, linear between rows as the bearing element reads it.
BearingCoefficients tableAt(const JournalBearingCurve& j, double speed) {
  std::size_t i = 1;
  while (i + 1 < j.speeds.size() && j.speeds[i] < speed) ++i;
  const double t = (speed - j.speeds[i - 1]) / (j.speeds[i] - j.speeds[i - 1]);
  const BearingCoefficients& a = j.coefficients[i - 1];
  const BearingCoefficients& b = j.coefficients[i];
  auto mix = [t](double x, double y) { return x + t * (y - x); };
  BearingCoefficients k;
  k.kyy = mix(a.kyy, b.kyy);
  k.kyz = mix(a.kyz, b.kyz);
  k.kzy = mix(a.kzy, b.kzy);
  k.kzz = mix(a.kzz, b.kzz);
  k.cyy = mix(a.cyy, b.cyy);
  k.cyz = mix(a.cyz, b.cyz);
  k.czy = mix(a.czy, b.czy);
  k.czz = mix(a.czz, b.czz);
  return k;
}

const CampbellOutcome& campbellOf(const Study& s) {
  REQUIRE(s.run);
  const CampbellOutcome* c = resultOf<CampbellOutcome>(s.run->analyses.at(0));
  REQUIRE(c);
  return *c;
}

}  // namespace

TEST_SUITE("rotor decks") {
  TEST_CASE("finite journal bearing deck: Raimondi and Boyd's eps = 0.6 at S = 0.121") {
    const Study s = solveDeckText(kRaimondiBoydDeck, "raimondi_boyd.yaml");
    const CampbellOutcome& c = campbellOf(s);
    REQUIRE(c.journals.size() == 1);
    const JournalBearingCurve& j = c.journals.front();
    // The table gives S to three digits: S = 0.121 +- 0.0005 spans eps 0.6 +- 0.0013 (dS/deps
    // = -0.38 here); the 288 x 36 film is converged to 1e-3 in S.
    CHECK(std::abs(j.eccentricity.front() - 0.6) < 0.0015);
    // The modified Sommerfeld number the outputs write, S_s = pi S (L/D)^2.
    CHECK(j.sommerfeld.front() == doctest::Approx(std::numbers::pi * 0.121).epsilon(1e-12));
  }

  TEST_CASE("finite journal bearing deck: oil whip of a rigid rotor against Lund's threshold") {
    const Study s = solveDeckText(kRigidRotorDeck, "rigid_rotor_long_bearings.yaml");
    const CampbellOutcome& c = campbellOf(s);
    REQUIRE(c.journals.size() == 2);
    REQUIRE(c.onset.has_value());
    // The threshold: where half the rotor's mass is the bearing's threshold mass (bisection on
    // the speed).
    const double half = (500 + 7850 * std::numbers::pi / 4 * 0.1 * 0.1 * 0.2) / 2;
    const JournalBearingCurve& j = c.journals.front();
    auto margin = [&](double speed) { return thresholdMass(tableAt(j, speed)) - half; };
    double lo = j.speeds.front(), hi = j.speeds.back();
    REQUIRE(margin(lo) > 0);
    REQUIRE(margin(hi) < 0);
    for (int i = 0; i < 100; ++i) ((margin((lo + hi) / 2) > 0) ? lo : hi) = (lo + hi) / 2;
    const double threshold = (lo + hi) / 2 * 30 / std::numbers::pi;
    MESSAGE("rigid rotor on L/D 1.5 bearings: onset " << c.onset->rpm << " rpm, threshold "
                                                      << threshold << " rpm");
    // Both roots to 1e-10 of the speed; the shaft's flexibility (film / shaft stiffness
    // ~ 2e-5) is what separates them.
    CHECK(relError(c.onset->rpm, threshold) < 1e-4);
    CHECK(c.onset->whirl == Whirl::forward);
  }

  TEST_CASE("finite journal bearing deck: the shipped compressor on L/D 1.2 bearings") {
    const Study s = solveShippedDeck("compressor_rotor_long_bearings.yaml");
    CHECK(checkAllPass(s) == 1);
    const CampbellOutcome& c = *resultOf<CampbellOutcome>(s.run->analyses.at(2));
    REQUIRE(c.journals.size() == 2);
    // The weight share: the rotor is symmetric about its middle, each bearing carries half.
    const double mass = compressorRotorMass();
    for (const JournalBearingCurve& j : c.journals) {
      // Gravity's share from the beam model's reactions: the symmetric rotor's half, to the
      // static solve's round-off.
      CHECK(j.journal.load == doctest::Approx(mass * 9.81 / 2).epsilon(1e-9));
      const std::size_t mid = j.speeds.size() / 2;
      const JournalOperatingPoint direct = finiteJournalPoint(j.journal, j.speeds[mid], {72, 10});
      CHECK(j.eccentricity[mid] == doctest::Approx(direct.eccentricity).epsilon(1e-12));
      CHECK(j.attitude[mid] == doctest::Approx(direct.attitude).epsilon(1e-12));
      CHECK(j.coefficients[mid].kyz == doctest::Approx(direct.coefficients.kyz).epsilon(1e-12));
      CHECK(j.coefficients[mid].czz == doctest::Approx(direct.coefficients.czz).epsilon(1e-12));
      // The longer film runs at a lower eccentricity than the short theory's L/D = 0.5
      // bearing of compressor_rotor.yaml at the same speed and load.
      PlainJournal half = j.journal;
      half.length = 0.5 * half.diameter;
      CHECK(j.eccentricity[mid] < eccentricityRatio(half, j.speeds[mid]));
    }
    // The plain journals' cross-coupling is real: the summary shows it as computed (the
    // round-off floor of the tilting-pad deck's summary keeps it).
    std::ostringstream summary;
    cli::printRotor(summary, s.run->analyses.at(2), c);
    CAPTURE(summary.str());
    for (const JournalBearingCurve& j : c.journals)
      for (const BearingCoefficients& k : {j.coefficients.front(), j.coefficients.back()}) {
        CHECK(std::abs(k.kyz) > 0.1 * k.kyy);
        const std::string shown =
            ", kxy " + cli::formatValue(k.kyz) + ", kyx " + cli::formatValue(k.kzy) + " N/m";
        CHECK(summary.str().find(shown) != std::string::npos);
      }
  }
}

TEST_SUITE("rotor decks") {
  TEST_CASE("finite journal bearing deck: a wrong model or grid is named") {
    auto deckWith = [](const std::string& bearing) {
      return std::string(R"(
title: a journal
model: {dimension: lateral}
materials: [{name: steel, E: 2.1e11, nu: 0.3, rho: 7850}]
sections: [{name: shaft, shape: circle, D: 100 mm}]
segments: [{name: shaft, length: 0.2, section: shaft, elements: 2}]
bearings:
  - {name: A, at: start, type: plain-journal, D: 100 mm, c: 100 um, mu: 0.02 Pa s,
     from_rpm: 3000, to_rpm: 6000, steps: 2, )") +
             bearing + "}\n  - {name: B, at: end, kxx: 1e8, kyy: 1e8}\n";
    };
    auto messageOf = [&](const std::string& bearing) {
      const DeckError e = readingError(deckWith(bearing), "journal.yaml");
      CHECK(e.place().line == 9);
      return e.message();
    };
    CHECK(messageOf("L: 150 mm, load: 1000 N, model: short")
              .find("the short-bearing theory holds for L/D <= 1 (here L/D = 1.5); use model: "
                    "finite") != std::string::npos);
    CHECK(messageOf("L: 50 mm, load: 1000 N, model: fnite").find("did you mean 'finite'") !=
          std::string::npos);
    CHECK(messageOf("L: 50 mm, load: 1000 N, grid: {axial: 4}")
              .find("a film grid belongs to model: finite") != std::string::npos);
    CHECK(messageOf("L: 150 mm, load: 1000 N, grid: {axial: 1}").find("between 2 and 500") !=
          std::string::npos);
    CHECK(messageOf("L: 150 mm, load: 1000 N, grid: {radial: 4}")
              .find("unknown key in a film grid") != std::string::npos);
    // A load the film carries only on a film thinner than 1 % of c, at the slowest speed.
    CHECK(messageOf("L: 150 mm, load: 1e7 N").find("the journal touches the bearing") !=
          std::string::npos);
    // The default above L/D = 1 is the finite film, and reads.
    const Study s = solveDeckText(deckWith("L: 150 mm, load: 1000 N") +
                                      "analyses: [{type: campbell, name: c, "
                                      "modes: 2, from_rpm: 3000, to_rpm: 6000, steps: 2}]\n",
                                  "journal.yaml");
    REQUIRE(s.run);
  }
}

// `beamrotor converge` on every shipped deck with its default quantity: the first one that
// changes with the discretisation, never a rigid-body property or a quantity exact on any
// mesh when another one converges; the orders it measures against the elements' and the time
// scheme's known orders.
#include <doctest/doctest.h>

#include <map>
#include <set>

#include "problems/converge/ConvergeStudy.hpp"
#include "problems/deck/DeckReader.hpp"
#include "tests/problems/DeckTestSupport.hpp"

using namespace beamrotor;

namespace {

/// The default study of a shipped deck: 3 levels (enough to extrapolate), one run per level.
ConvergeStudy defaultStudyOf(const std::filesystem::path& deck) {
  ConvergeOptions options;
  options.levels = 3;
  options.repeats = 1;
  return runConvergence(readDeck(loadDeckFile(deck), {}), options);
}

const ConvergeSeries& firstSeries(const ConvergeStudy& s) {
  REQUIRE_FALSE(s.series.empty());
  return s.series.front();
}

}  // namespace

TEST_SUITE("converge decks") {
  TEST_CASE("every shipped deck converges with its default quantity") {
    // What each deck's default should be: the first quantity that depends on the mesh (or on
    // the time step for a transient deck without beams).
    const std::map<std::string, std::string> expected{
        {"cantilever", "frequency 1"},         // its tip values and stress are exact on any mesh
        {"forme_shaft", "frequency 1"},        // the rigid-body checks come first, mesh-free
        {"forme_shaft_rotor", "frequency 1"},  // the rotor analysis' lowest whirl frequency
        {"mo10", "history phi maxabs"},        // no beams: the time step
        {"simply_supported", "frequency 1"}};
    // Decks of mechanisms alone (no beams, no points: problems/deck/FORMAT.md, "Mechanisms
    // without a model") have no mesh or time step to refine: the study refuses them, naming
    // the deck and its first analysis' line.
    const std::set<std::string> withoutModel{"forme_shaft_two_dof", "snt32_drive"};
    for (const auto& deck : test::shippedDecks()) {
      const std::string stem = deck.stem().string();
      CAPTURE(stem);
      if (withoutModel.count(stem)) {
        try {
          defaultStudyOf(deck);
          FAIL("a deck without a model was studied");
        } catch (const DeckError& e) {
          CHECK(e.message().find("no mesh or time step to refine") != std::string::npos);
          CHECK(e.place().line > 0);
        }
        continue;
      }
      ConvergeStudy study;
      REQUIRE_NOTHROW(study = defaultStudyOf(deck));
      MESSAGE(stem << ": " << study.quantity << " (" << study.choice << ")");
      CHECK_FALSE(study.choice.empty());
      if (expected.count(stem)) CHECK(study.quantity == expected.at(stem));
      // The first method (Euler-Bernoulli, or the deck's scheme) solves every level.
      const ConvergeSeries& s = firstSeries(study);
      CHECK(s.failure.empty());
      CHECK(s.levels.size() == 3);
      for (const ConvergeLevel& l : s.levels) CHECK(std::isfinite(l.value));
    }
  }

  TEST_CASE("mo10: a time-step study, Newmark's order 2") {
    const ConvergeStudy study = defaultStudyOf(test::problemsDir() / "mo10.yaml");
    CHECK(study.refinement == "time step");
    CHECK(study.check == "phi_max vs closed form");
    const ConvergeSeries& s = firstSeries(study);
    REQUIRE(s.levels.size() == 3);
    CHECK(s.levels[1].steps == 2 * s.levels[0].steps);
    // Average acceleration: period error (k dt)^2 / 12 per radian (Newmark 1959), order 2;
    // the peak over sampled steps adds a dt^2 sampling term too. Measured 2.0 (+-0.05).
    REQUIRE(s.levels[2].order);
    CHECK(*s.levels[2].order == doctest::Approx(2).epsilon(0.05));
  }

  TEST_CASE("a deck whose every quantity is exact on any mesh says so") {
    // pump_rod_crank_cycle: statics of Euler-Bernoulli beams under end loads and settlements,
    // exact on every mesh; its first check is studied (against the paper's rounded figure),
    // and its value is the same on every level to round-off (cond(K) * eps ~ 1e-12 here).
    const ConvergeStudy study = defaultStudyOf(test::problemsDir() / "pump_rod_crank_cycle.yaml");
    CHECK(study.choice.find("no quantity of the deck changes") != std::string::npos);
    const ConvergeSeries& s = firstSeries(study);
    for (const ConvergeLevel& l : s.levels)
      CHECK(std::abs(l.value - s.levels.front().value) < 1e-9 * std::abs(l.value));
  }
}

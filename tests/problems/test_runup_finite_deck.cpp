// A run-up on finite journal films through the deck path: problems/journal_runup.yaml with its
// bearings' `model: finite` (Reynolds' equation on a grid), shortened. The journals start where
// the finite film carries the load (finiteJournalPoint on the deck's grid), and the run's energy
// account closes step by step with the work done against the films.
#include <doctest/doctest.h>

#include <cmath>
#include <numbers>
#include <string>

#include "elements/FiniteJournalBearing.hpp"
#include "tests/problems/DeckTestSupport.hpp"

using namespace beamrotor;

namespace {

/// The shipped deck's text with `from` everyReplaced by `to` (which must occur).
std::string everyReplaced(std::string text, const std::string& from, const std::string& to) {
  for (std::size_t at = text.find(from); at != std::string::npos;
       at = text.find(from, at + to.size()))
    text.replace(at, from.size(), to);
  return text;
}

}  // namespace

TEST_SUITE("rotor decks") {
  TEST_CASE("run-up on finite journal films from a deck: the film's own start, energy balance") {
    std::string deck = test::fileContents(test::problemsDir() / "journal_runup.yaml");
    REQUIRE(deck.find("mu: 0.02 Pa*s,") != std::string::npos);
    // A coarse grid and 0.1 s keep the test short (the film and its coefficients share any
    // grid); the closed-form speed check belongs to the 3 s run.
    deck = everyReplaced(deck, "mu: 0.02 Pa*s,",
                    "mu: 0.02 Pa*s, model: finite, grid: {circumferential: 36, axial: 4},");
    deck = everyReplaced(deck, "duration: 3 s", "duration: 0.1 s");
    deck = deck.substr(0, deck.find("\nchecks:"));
    const Study s = test::solveDeckText(deck, "finite_runup.yaml");
    const auto* r = resultOf<RunUpOutcome>(s.run->analyses.front());
    REQUIRE(r);
    const RunUpResult& u = r->runUp;
    REQUIRE(u.journals.size() == 2);
    // The deck's bearing: D 30 mm, L 12 mm, c 40 um, mu 0.02 Pa s, 98.1 N, at 1200 rpm. The
    // run starts where the same film on the same grid carries the load.
    const PlainJournal journal{0.03, 0.012, 40e-6, 0.02, 98.1};
    const double eps =
        finiteJournalPoint(journal, 1200 * std::numbers::pi / 30, {36, 4}).eccentricity;
    MESSAGE("finite start eps " << u.journals[0].startEccentricity << " (point " << eps
                                << "), largest " << u.journals[0].largestEccentricity
                                << ", Newton " << u.newtonIterations << " over " << u.steps
                                << " steps, at most " << u.mostNewtonIterations << ", "
                                << u.time.total << " s");
    for (const JournalTrack& j : u.journals) {
      // The deck's lengths (30 mm, 40 um) differ from these by an ulp, and the eccentricity is
      // a root found to 1e-10 of its bracket in log(eps / (1 - eps)): ~5e-10 in eps.
      CHECK(j.startEccentricity == doctest::Approx(eps).epsilon(1e-9));
      CHECK(j.largestEccentricity < 1);
    }
    // The average acceleration rule's energy identity (trapezoidal work of every force, the
    // films' included) holds step by step once the run is under way; the start puts the
    // massless journals on the linear steady orbit, off their films' balance, and the first
    // step's jump leaves a constant offset (1.4e-9 J here, 2.8e-10 J with the short films).
    // After it: round-off of the sums and Newton's 1e-10 c.
    const RunUpEnergy& e = u.energy;
    const std::size_t last = e.kinetic.size() - 1;
    const double drift = std::abs(e.balance(last) - e.balance(1));
    MESSAGE("energy: work " << e.work[last] << " J, film " << e.film[last] << " J, offset "
                            << e.balance(1) << " J, drift after the start " << drift << " J");
    CHECK(drift < 1e-9 * e.work[last]);
  }

  TEST_CASE("a finite film that cannot carry its load at the run-up's start is refused") {
    std::string deck = test::fileContents(test::problemsDir() / "journal_runup.yaml");
    deck = everyReplaced(deck, "mu: 0.02 Pa*s,",
                    "mu: 0.02 Pa*s, model: finite, grid: {circumferential: 36, axial: 4},");
    // At 10 rpm the film needs an eccentricity above 0.99 (0.74 at 1200 rpm).
    deck = everyReplaced(deck, "from_rpm: 1200", "from_rpm: 10");
    const std::string field = "    bearings: nonlinear";
    int line = 1;
    for (std::size_t k = 0; k < deck.find(field); ++k) line += deck[k] == '\n';
    const DeckError e = test::readingError(deck, "finite_runup.yaml");
    CAPTURE(e.message());
    CHECK(e.place().line == line);
    CHECK(e.message().find("bearing 'left' at the run-up's start speed (10 rpm)") !=
          std::string::npos);
    CHECK(e.message().find("start the run faster") != std::string::npos);
  }
}

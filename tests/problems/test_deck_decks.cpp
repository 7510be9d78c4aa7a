// Every deck shipped in problems/ solves and passes all of its checks; the pump rod deck
// reproduces the published reactions, and its parameters can be overridden.
#include <doctest/doctest.h>

#include "problems/run/Study.hpp"
#include "tests/Helpers.hpp"
#include "tests/problems/DeckTestSupport.hpp"

using namespace beamrotor;
using beamrotor::test::relError;

namespace {

StudyRequest request(const std::filesystem::path& deck, std::vector<std::string> sets = {}) {
  StudyRequest r;
  r.deckPath = deck.string();
  r.sets = std::move(sets);
  return r;
}

double reaction(const RunResult& run, const std::string& support, Dof d) {
  for (const AnalysisOutcome& a : run.analyses)
    if (staticsOf(a)) return staticsOf(a)->reaction(support, d);
  FAIL("no static analysis");
  return 0;
}

const std::filesystem::path kPumpRod = test::problemsDir() / "pump_rod.yaml";

}  // namespace

TEST_SUITE("decks") {
  TEST_CASE("every deck in problems/ solves and passes all its checks") {
    const auto decks = test::shippedDecks();
    REQUIRE(decks.size() >= 2);  // at least pump_rod and cantilever
    for (const auto& deck : decks) {
      CAPTURE(deck.filename().string());
      const Study s = solveStudy(request(deck));
      // A deck states its reference solution: at least one check must actually run.
      CHECK(test::checkAllPass(s) > 0);
    }
  }

  TEST_CASE("every deck in problems/ writes its results and charts without a warning") {
    // Writers are shared between analyses (captions, panels): a change made for one kind of
    // chart must not break another's gnuplot script, which would only show as a warning.
    for (const auto& deck : test::shippedDecks()) {
      const std::string name = deck.filename().string();
      CAPTURE(name);
      const test::SolvedDeck solved = test::solveShippedDeckToScratch(name, "charts-" + name);
      CHECK(solved.process.err.find("warning") == std::string::npos);
      CHECK((std::filesystem::exists(solved.dir / "results.json") ||
             std::filesystem::exists(solved.dir / "sweep.json")));
      std::filesystem::remove_all(solved.dir.parent_path());
    }
  }

  TEST_CASE("pump rod, variant A: the published reactions at eta = 0.4, w0 = 1 mm") {
    const Study s = solveStudy(request(kPumpRod));
    REQUIRE(s.run);
    const RunResult& run = *s.run;
    // Published (problems/scenes/README.md section 1) to 3 or 4 digits; tolerance half a unit of
    // the last printed digit, relative, as printed. Signs: the lowered left end is pulled down, the
    // seal pushes up.
    CHECK(relError(-reaction(run, "left", Dof::rz), 7.66e3) < 0.005 / 7.66);
    CHECK(relError(-reaction(run, "left", Dof::uy), 10.4e3) < 0.05 / 10.4);
    CHECK(relError(reaction(run, "middle", Dof::uy), 13.33e3) < 0.005 / 13.33);
    CHECK(relError(-reaction(run, "right", Dof::uy), 2.93e3) < 0.005 / 2.93);
    CHECK(relError(reaction(run, "right", Dof::rz), 797.05) < 0.005 / 797.05);
    // Equilibrium of vertical forces, P3 = P2 + P4: round-off only.
    const double sum = reaction(run, "left", Dof::uy) + reaction(run, "middle", Dof::uy) +
                       reaction(run, "right", Dof::uy);
    CHECK(std::abs(sum) < 1e-9 * 13.33e3);
    // The checks tied to eta = 0 (and to w0 = 5 mm) do not apply here, and say so.
    REQUIRE(run.skippedChecks.size() == 2);
    CHECK(run.skippedChecks[0] == "P3 published at eta = 0");
  }

  TEST_CASE("pump rod: overriding eta moves the middle support and changes its reaction") {
    const Study at04 = solveStudy(request(kPumpRod));
    const Study at02 = solveStudy(request(kPumpRod, {"eta=0.2"}));
    const Study at0 = solveStudy(request(kPumpRod, {"eta=0"}));
    REQUIRE(at02.run);
    REQUIRE(at0.run);
    const double p04 = reaction(*at04.run, "middle", Dof::uy);
    const double p02 = reaction(*at02.run, "middle", Dof::uy);
    const double p0 = reaction(*at0.run, "middle", Dof::uy);
    // The parameters after the override, in deck order.
    REQUIRE(at02.run->parameters.front().first == "eta");
    CHECK(at02.run->parameters.front().second == 0.2);
    // Published: 7.46 kN at eta = 0 (half a unit of the last digit) ...
    CHECK(relError(p0, 7.46e3) < 0.005 / 7.46);
    // ... rising monotonically to 13.33 kN at eta = 0.4, so eta = 0.2 lies strictly between.
    CHECK(p02 > 7.46e3);
    CHECK(p02 < 13.33e3);
    CHECK(std::abs(p02 - p04) > 1e3);  // far more than any round-off: the support moved
    // Checks tied to eta = 0.4 are not applicable at eta = 0.2; the closed forms still are.
    CHECK(at02.run->skippedChecks.size() == 8);
    for (const Check& c : at02.run->checks) CHECK(c.pass());
  }

  TEST_CASE("pump rod: the reactions are linear in w0") {
    const Study once = solveStudy(request(kPumpRod));
    const Study twice = solveStudy(request(kPumpRod, {"w0=2e-3"}));
    // Linear statics: doubling the prescribed deflection doubles every reaction exactly
    // (round-off only).
    for (const auto& [support, dof] : {std::pair{"left", Dof::rz},
                                       {"left", Dof::uy},
                                       {"middle", Dof::uy},
                                       {"right", Dof::uy},
                                       {"right", Dof::rz}})
      CHECK(relError(reaction(*twice.run, support, dof), 2 * reaction(*once.run, support, dof)) <
            1e-12);
  }
}

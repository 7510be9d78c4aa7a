// The command line's messages for the commonest slips, end to end through the executable: a
// mistyped subcommand, every beam formulation a deck accepts given as --formulation, and a
// --set value that is not a number.
#include <doctest/doctest.h>

#include <string>

#include "problems/deck/structure/Formulations.hpp"
#include "tests/problems/DeckTestSupport.hpp"

using namespace beamrotor;
using namespace beamrotor::test;

namespace {

bool holds(const std::string& text, const std::string& part) {
  return text.find(part) != std::string::npos;
}

/// The cantilever deck's text with its model formulation replaced by `name`.
std::string cantileverWithFormulation(const std::string& name) {
  std::string text = fileContents(problemsDir() / "cantilever.yaml");
  const std::string deckLine = "formulation: euler-bernoulli";
  const std::size_t at = text.find(deckLine);
  REQUIRE(at != std::string::npos);
  return text.replace(at, deckLine.size(), "formulation: " + name);
}

}  // namespace

TEST_SUITE("command line messages") {
  TEST_CASE("a mistyped subcommand is named, with the closest command and the list") {
    const ProcessResult slove = runBeamrotor({"slove", "problems/cantilever.yaml"});
    CHECK(slove.exitCode == 2);
    CHECK(slove.out.empty());
    CHECK(holds(slove.err, "'slove' is not a command; did you mean solve?"));
    CHECK(holds(slove.err, "(commands: solve, check, bench, report, converge, overlay, study; beamrotor --help)"));
    const ProcessResult chekc = runBeamrotor({"chekc", "problems/cantilever.yaml"});
    CHECK(chekc.exitCode == 2);
    CHECK(holds(chekc.err, "did you mean check?"));
    // Nothing close: no suggestion, still the list.
    const ProcessResult far = runBeamrotor({"frobnicate"});
    CHECK(far.exitCode == 2);
    CHECK_FALSE(holds(far.err, "did you mean"));
    CHECK(holds(far.err, "'frobnicate' is not a command"));
    // A real subcommand and options before it are untouched.
    CHECK(runBeamrotor({"--version"}).exitCode == 0);
  }

  TEST_CASE("--formulation takes every name a deck's formulation: takes, with the same effect") {
    const std::vector<std::string> names = formulationNames();
    REQUIRE(names.size() == 4);
    std::vector<double> tipByName;
    for (const std::string& name : names) {
      CAPTURE(name);
      StudyRequest request = shippedDeckRequest("cantilever.yaml");
      request.formulation = name;
      const Study byOption = solveStudy(request);
      const Study byDeck = solveDeckText(cantileverWithFormulation(name), "cantilever.yaml");
      REQUIRE(byOption.run);
      REQUIRE(byDeck.run);
      REQUIRE(byOption.run->checks.size() == byDeck.run->checks.size());
      // The same model built by two paths: the same numbers bit for bit.
      for (std::size_t k = 0; k < byOption.run->checks.size(); ++k) {
        CAPTURE(byOption.run->checks[k].name);
        CHECK(byOption.run->checks[k].computed == byDeck.run->checks[k].computed);
      }
      tipByName.push_back(byOption.run->checks.front().computed);  // tip deflection
      const ProcessResult cli =
          runBeamrotor({"check", "problems/cantilever.yaml", "--formulation", name});
      CHECK(cli.exitCode != 2);  // 3 where a check written for Euler-Bernoulli fails
      CHECK(holds(cli.out, "formulation: " + name + " for every segment"));
    }
    // Each theory's tip deflection differs from Euler-Bernoulli's (the option took effect): shear
    // softens the rod (L/D = 40: by ~1e-3), the fully integrated linear element locks (stiffer).
    for (std::size_t k = 1; k < names.size(); ++k) {
      CAPTURE(names[k]);
      CHECK(tipByName[k] != tipByName[0]);
    }
    const ProcessResult bad =
        runBeamrotor({"check", "problems/cantilever.yaml", "--formulation", "timoshenko-linear"});
    CHECK(bad.exitCode == 2);
    CHECK(holds(bad.err, "expected euler-bernoulli, timoshenko, timoshenko-linear-full, "
                         "timoshenko-linear-reduced"));
  }

  TEST_CASE("--set with a value that is not a number names the value and why") {
    const ProcessResult name = runBeamrotor({"solve", "problems/cantilever.yaml", "--set", "P=abc"});
    CHECK(name.exitCode == 2);
    CHECK(holds(name.err, "--set P=abc: cannot evaluate 'abc': unknown name 'abc'"));
    CHECK(holds(name.err, "not of other parameters"));
    CHECK_FALSE(holds(name.err, "defined so far"));
    const ProcessResult half =
        runBeamrotor({"solve", "problems/cantilever.yaml", "--set", "P=2*"});
    CHECK(half.exitCode == 2);
    CHECK(holds(half.err, "--set P=2*: cannot evaluate '2*': "));
    CHECK(holds(half.err, "not of other parameters"));
    // A constant expression is still fine.
    StudyRequest request = shippedDeckRequest("cantilever.yaml", {"P=2*600"});
    CHECK(solveStudy(request).run->parameters[2].second == 1200);
  }
}

// `beamrotor solve` warns when a static mesh is past the point where round-off outweighs
// discretisation error (problems/run/OverRefinementWarning.hpp), and the shipped decks don't.
#include <doctest/doctest.h>

#include <fstream>
#include <sstream>

#include "tests/problems/DeckTestSupport.hpp"

using namespace beamrotor;
using namespace beamrotor::test;

namespace {

const std::filesystem::path kFixture = std::filesystem::path(BEAMROTOR_SOURCE_DIR) /
                                       "tests/problems/over_refined/cantilever_4000.yaml";

/// The fixture's statics with its 4000 elements replaced by `elements`.
std::string cantileverText(int elements) {
  std::ifstream in(kFixture);
  std::stringstream s;
  s << in.rdbuf();
  std::string text = s.str();
  const std::string from = "elements: 4000";
  text.replace(text.find(from), from.size(), "elements: " + std::to_string(elements));
  return text;
}

const Check& tipCheck(const RunResult& run) {
  for (const Check& c : run.checks)
    if (c.name == "tip deflection") return c;
  throw std::logic_error("no tip deflection check");
}

}  // namespace

TEST_SUITE("over-refinement warning") {
  TEST_CASE("a grossly over-refined cantilever warns, and its round-off is real") {
    StudyRequest request;
    request.deckPath = "cantilever_fine.yaml";
    const Study coarse = solveStudyText(cantileverText(16), request);
    const Study fine = solveStudyText(cantileverText(4000), request);
    CHECK(coarse.run->analyses[0].warnings.empty());
    REQUIRE(fine.run->analyses[0].warnings.size() == 1);
    CHECK(fine.run->analyses[0].warnings[0].find("round-off") != std::string::npos);
    // Hermite elements are exact for the tip load: at 16 elements the deck's closed form holds
    // to its 1e-9; at 4000 the error is all round-off and well past that (the warning is right).
    CHECK(tipCheck(*coarse.run).relError() < 1e-9);
    CHECK(tipCheck(*fine.run).relError() > 1e-7);
  }

  TEST_CASE("solve prints the warning and writes it to results.json") {
    const auto dir = scratchDir("over_refinement_warning");
    const ProcessResult p =
        runBeamrotor({"solve", kFixture.string(), "--out", (dir / "out").string()});
    CHECK(p.exitCode == 0);  // a warning, not an error
    CHECK(p.out.find("warning: static: mesh past the point where round-off") != std::string::npos);
    std::ifstream json(dir / "out" / "results.json");
    const auto doc = nlohmann::json::parse(json);
    CHECK(doc.at("analyses").at(0).at("warnings").size() == 1);
    std::filesystem::remove_all(dir);
  }

  TEST_CASE("no shipped deck warns") {
    for (const auto& path : shippedDecks()) {
      CAPTURE(path.string());
      StudyRequest request;
      request.deckPath = path.string();
      request.noSweep = true;
      for (const RunResult* run : runsOf(solveStudy(request)))
        for (const AnalysisOutcome& a : run->analyses) CHECK(a.warnings.empty());
    }
  }
}

// `beamrotor study` through the executable: its results directory and summary lines, and the
// messages for study options that cannot be used (exit 2, naming the option and the deck).
#include <doctest/doctest.h>

#include <string>

#include "tests/problems/DeckTestSupport.hpp"

using namespace beamrotor::test;

namespace {

bool says(const std::string& text, const std::string& part) {
  return text.find(part) != std::string::npos;
}

}  // namespace

TEST_SUITE("study command line") {
  TEST_CASE("a grid study writes its table, summary and worst point") {
    const auto scratch = scratchDir("study-cli");
    const ProcessResult p =
        runBeamrotor({"study", "problems/pump_rod.yaml", "--sweep", "eta=0,0.4", "--sweep",
                      "w0=1e-3,2e-3", "--output", "stress max <= 100 MPa", "--out",
                      (scratch / "s").string()});
    REQUIRE_MESSAGE(p.exitCode == 0, p.err);
    CHECK(says(p.out, "4 points (grid), 0 failed"));
    CHECK(says(p.out, "stress max: min"));
    CHECK(says(p.out, "points/s"));
    CHECK(std::filesystem::exists(scratch / "s" / "study.csv"));
    CHECK(std::filesystem::exists(scratch / "s" / "worst" / "results.json"));
    std::filesystem::remove_all(scratch);
  }

  TEST_CASE("bad study options name themselves and exit 2") {
    const auto badDistribution = runBeamrotor(
        {"study", "problems/pump_rod.yaml", "--sample", "w0=normall(1e-3,1e-4)", "--samples", "5"});
    CHECK(badDistribution.exitCode == 2);
    CHECK(says(badDistribution.err, "--sample w0=normall(1e-3,1e-4)"));
    CHECK(says(badDistribution.err, "did you mean 'normal'?"));
    const auto badOutput = runBeamrotor(
        {"study", "problems/pump_rod.yaml", "--sweep", "eta=0,0.4", "--output", "reaction lefft uy"});
    CHECK(badOutput.exitCode == 2);
    CHECK(says(badOutput.err, "--output reaction lefft uy"));
    CHECK(says(badOutput.err, "did you mean 'left'?"));
    const auto noCount =
        runBeamrotor({"study", "problems/pump_rod.yaml", "--sample", "w0=normal(1e-3,1e-4)"});
    CHECK(noCount.exitCode == 2);
    CHECK(says(noCount.err, "samples"));
    const auto wrongUnit = runBeamrotor(
        {"study", "problems/pump_rod.yaml", "--sample", "w0=uniform(1 kg,2 kg)", "--samples", "5"});
    CHECK(wrongUnit.exitCode == 2);
    CHECK(says(wrongUnit.err, "w0"));
    const auto nothing = runBeamrotor({"study", "problems/cantilever.yaml"});
    CHECK(nothing.exitCode == 2);
    CHECK(says(nothing.err, "nothing to vary"));
  }
}

// End to end: the beamrotor executable's exit codes, its one-line error messages, help and
// version, and that a failed run leaves no results directory behind.
#include <doctest/doctest.h>

#include <algorithm>
#include <fstream>
#include <iterator>

#include "tests/problems/DeckTestSupport.hpp"

using namespace beamrotor::test;

namespace {

int lineCount(const std::string& s) { return int(std::count(s.begin(), s.end(), '\n')); }

}  // namespace

TEST_SUITE("command line") {
  TEST_CASE("--help and --version") {
    const ProcessResult help = runBeamrotor({"--help"});
    CHECK(help.exitCode == 0);
    CHECK(help.out.find("solve") != std::string::npos);
    CHECK(help.out.find("check") != std::string::npos);
    const ProcessResult solveHelp = runBeamrotor({"solve", "--help"});
    CHECK(solveHelp.exitCode == 0);
    CHECK(solveHelp.out.find("--set") != std::string::npos);
    CHECK(runBeamrotor({"check", "--help"}).exitCode == 0);
    const ProcessResult version = runBeamrotor({"--version"});
    CHECK(version.exitCode == 0);
    CHECK(version.out.find(BEAMROTOR_VERSION) != std::string::npos);
  }

  TEST_CASE("bad command lines are input errors (exit 2)") {
    CHECK(runBeamrotor({}).exitCode == 2);                        // no subcommand
    CHECK(runBeamrotor({"solve"}).exitCode == 2);                 // no deck
    CHECK(runBeamrotor({"frobnicate"}).exitCode == 2);
    CHECK(runBeamrotor({"solve", "problems/pump_rod.yaml", "--bogus"}).exitCode == 2);
  }

  TEST_CASE("solve writes the results and prints where they are") {
    const auto out = scratchDir("cli-solve") / "pump";
    const ProcessResult r = runBeamrotor({"solve", "problems/pump_rod.yaml", "--out", out.string()});
    CAPTURE(r.err);
    CHECK(r.exitCode == 0);
    CHECK(r.err.empty());
    CHECK(r.out.find("results: " + out.string()) != std::string::npos);
    CHECK(r.out.find("PASS") != std::string::npos);
    CHECK(r.out.find("FAIL") == std::string::npos);
    CHECK(std::filesystem::exists(out / "results.json"));
    std::filesystem::remove_all(out.parent_path());
  }

  TEST_CASE("check passes the shipped decks (exit 0) and fails a wrong reference (exit 3)") {
    CHECK(runBeamrotor({"check", "problems/cantilever.yaml"}).exitCode == 0);
    CHECK(runBeamrotor({"check", "problems/pump_rod.yaml", "--set", "eta=0.2"}).exitCode == 0);
    // The cantilever deck with its root-force reference doubled: that check must fail.
    const auto dir = scratchDir("cli-check");
    const auto deck = dir / "wrong.yaml";
    std::ifstream in(problemsDir() / "cantilever.yaml");
    std::string text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
    text.replace(text.find("reference: P, tolerance"), 23, "reference: 2*P, tolerance");
    std::ofstream(deck) << text;
    const ProcessResult r = runBeamrotor({"check", deck.string()});
    CHECK(r.exitCode == 3);
    CHECK(r.out.find("FAIL") != std::string::npos);
    std::filesystem::remove_all(dir);
  }

  TEST_CASE("a malformed deck: one line on stderr, exit 2, no results directory") {
    const auto out = scratchDir("cli-malformed") / "never";
    const ProcessResult r = runBeamrotor(
        {"solve", "tests/problems/malformed/negative_length.yaml", "--out", out.string()});
    CHECK(r.exitCode == 2);
    CHECK(lineCount(r.err) == 1);
    CHECK(r.err.rfind("tests/problems/malformed/negative_length.yaml:12:14: segments[1].length: "
                      "must be positive, got -0.5",
                      0) == 0);
    CHECK_FALSE(std::filesystem::exists(out));
  }

  TEST_CASE("other input errors: missing file, binary file, unknown --set") {
    ProcessResult r = runBeamrotor({"solve", "problems/no_such_deck.yaml"});
    CHECK(r.exitCode == 2);
    CHECK(lineCount(r.err) == 1);
    CHECK(r.err.find("problems/no_such_deck.yaml: cannot open") == 0);

    r = runBeamrotor({"check", "tests/problems/malformed/binary_bytes.yaml"});
    CHECK(r.exitCode == 2);
    CHECK(lineCount(r.err) == 1);
    CHECK(r.err.find("binary_bytes.yaml:4:7: not a text deck") != std::string::npos);

    r = runBeamrotor({"check", "problems/pump_rod.yaml", "--set", "etta=0.2"});
    CHECK(r.exitCode == 2);
    CHECK(lineCount(r.err) == 1);
    CHECK(r.err.find("problems/pump_rod.yaml: --set etta=0.2: no parameter 'etta'") == 0);
    CHECK(r.err.find("did you mean 'eta'?") != std::string::npos);

    r = runBeamrotor({"check", "problems/pump_rod.yaml", "--set", "eta=1/0"});
    CHECK(r.exitCode == 2);
    CHECK(r.err.find("evaluates to inf") != std::string::npos);
  }

  TEST_CASE("a structure that is not supported: exit 1, the deck and the free dofs named") {
    const auto out = scratchDir("cli-unsupported") / "never";
    const ProcessResult r = runBeamrotor(
        {"solve", "tests/problems/malformed/unsupported_structure.yaml", "--out", out.string()});
    CHECK(r.exitCode == 1);
    CHECK(lineCount(r.err) == 1);
    CHECK(r.err.find("tests/problems/malformed/unsupported_structure.yaml:17:5: analyses[0]: "
                   "static analysis:") == 0);
    CHECK(r.err.find("not fully supported") != std::string::npos);
    CHECK(r.err.find("rz") != std::string::npos);
    CHECK_FALSE(std::filesystem::exists(out));
  }
}

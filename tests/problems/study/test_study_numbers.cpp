// Command-line numbers read strictly (problems/cli/WholeNumberOption.hpp): a count or seed is
// a whole number in its range, written in digits, and a refusal names the option; and study
// limits from below (`>=`, `lower_limit:`), whose probability is checked against the normal
// distribution's tail.
#include <doctest/doctest.h>

#include <cmath>
#include <cstdio>

#include "problems/cli/WholeNumberOption.hpp"
#include "problems/study/DesignStudyRun.hpp"
#include "problems/study/Sampling.hpp"
#include "tests/problems/DeckTestSupport.hpp"
#include "tests/problems/PumpRodReference.hpp"

using namespace beamrotor;
using namespace beamrotor::test;

namespace {

bool mentions(const std::string& text, const std::string& part) {
  return text.find(part) != std::string::npos;
}

ProcessResult sampledStudy(const std::string& option, const std::string& value) {
  return runBeamrotor({"study", "problems/pump_rod.yaml", "--sample", "w0=normal(1e-3,1e-4)",
                       "--samples", option == "--samples" ? value : "2", option, value, "--out",
                       (scratchDir("study-numbers") / "s").string()});
}

}  // namespace

TEST_SUITE("command line numbers") {
  TEST_CASE("a whole number is digits within its range; anything else says why") {
    using beamrotor::cli::wholeNumberProblem;
    CHECK(wholeNumberProblem("0", 0, UINT64_MAX).empty());
    CHECK(wholeNumberProblem("18446744073709551615", 0, UINT64_MAX).empty());
    CHECK(mentions(wholeNumberProblem("18446744073709551616", 0, UINT64_MAX), "(too large)"));
    CHECK(mentions(wholeNumberProblem("-1", 0, UINT64_MAX), "got '-1' (negative)"));
    CHECK(mentions(wholeNumberProblem("1.5", 0, 10), "got '1.5' (not a whole number)"));
    CHECK(mentions(wholeNumberProblem("2e3", 0, 10000), "(not a whole number)"));
    CHECK(mentions(wholeNumberProblem("0x10", 0, 100), "got '0x10'"));
    CHECK(mentions(wholeNumberProblem(" 5", 0, 100), "got ' 5'"));
    CHECK(mentions(wholeNumberProblem("", 0, 100), "got ''"));
    CHECK(mentions(wholeNumberProblem("0", 1, 1024), "expected a whole number from 1 to 1024"));
    CHECK(mentions(wholeNumberProblem("1025", 1, 1024), "(too large)"));
  }

  TEST_CASE("--seed -1, 2^64 and 1.5 are refused naming --seed; 2^64 - 1 is taken as it is") {
    for (const char* bad : {"-1", "18446744073709551616", "1.5"}) {
      CAPTURE(bad);
      const ProcessResult p = sampledStudy("--seed", bad);
      CHECK(p.exitCode == 2);
      CHECK(mentions(p.err, "--seed: expected a whole number from 0 to 18446744073709551615, got '" +
                            std::string(bad) + "'"));
    }
    const auto scratch = scratchDir("study-seed");
    DesignStudyRequest r;
    r.deckPath = (problemsDir() / "pump_rod.yaml").string();
    r.outDir = (scratch / "s").string();
    r.study.samples = {"w0=normal(1e-3,1e-4)"};
    r.study.count = 2;
    r.study.seed = UINT64_MAX;
    const ProcessResult largest = runBeamrotor(
        {"study", r.deckPath, "--sample", r.study.samples[0], "--samples", "2", "--seed",
         "18446744073709551615", "--out", r.outDir});
    REQUIRE(largest.exitCode == 0);
    const auto summary = nlohmann::json::parse(fileContents(scratch / "s" / "summary.json"));
    CHECK(summary["seed"].get<std::uint64_t>() == UINT64_MAX);
    std::filesystem::remove_all(scratch);
  }

  TEST_CASE("--samples, --threads, bench and converge counts are refused alike") {
    CHECK(mentions(sampledStudy("--samples", "1.5").err, "--samples: expected a whole number"));
    CHECK(mentions(sampledStudy("--samples", "99999999999999999999").err, "(too large)"));
    CHECK(mentions(sampledStudy("--threads", "0").err, "--threads: expected a whole number from 1"));
    const ProcessResult bench = runBeamrotor({"bench", "--kind", "planar", "--elements", "1e3"});
    CHECK(bench.exitCode == 2);
    CHECK(mentions(bench.err, "--elements: expected a whole number from 4 to 100000000, got '1e3'"));
    const ProcessResult levels =
        runBeamrotor({"converge", "problems/cantilever.yaml", "--levels", "2.5"});
    CHECK(levels.exitCode == 2);
    CHECK(mentions(levels.err, "--levels: expected a whole number"));
  }
}

TEST_SUITE("design studies") {
  TEST_CASE("a lower limit (>=): the probability of falling below it is a normal tail") {
    // The middle force is c w0 (linear statics, w0 the only load): P(c w0 < L) =
    // Phi((L / c - mu) / sd), c from the closed form at w0 = 1; L where that is 0.1.
    // Tolerance: 5 binomial standard errors sqrt(p (1 - p) / n).
    const auto scratch = scratchDir("study-lower-limit");
    PumpRod rod;  // eta = 0.4, the deck's
    const double c = pumpRodInitialParameters(rod, 1.0, true).middleForce;
    const double mu = 1e-3, sd = 0.2e-3, p = 0.1, n = 1000;
    const double limit = c * (mu + sd * normalQuantile(p));
    DesignStudyRequest r;
    r.deckPath = (problemsDir() / "pump_rod.yaml").string();
    r.outDir = (scratch / "s").string();
    r.study.samples = {"w0=normal(1e-3,0.2e-3)"};
    r.study.count = (long long)n;
    r.study.seed = 3;
    char output[96];
    std::snprintf(output, sizeof output, "reaction middle uy >= %.17g", limit);
    r.study.outputs = {output};
    const DesignStudyOutcome o = runDesignStudy(r);
    const auto& out = o.summary["outputs"][0];
    CHECK(out["limit_is"] == "lower");
    const double estimate = out["exceedance"]["probability"].get<double>();
    CHECK(std::abs(estimate - p) < 5 * std::sqrt(p * (1 - p) / n));
    // The worst point of a lower limit is the smallest value.
    CHECK(out["worst"]["value"] == out["min"]);
    std::filesystem::remove_all(scratch);
  }
}

TEST_SUITE("study command line") {
  TEST_CASE("a lognormal's sigma that cannot be read, or has a unit, is bad input naming --sample") {
    // Found by fuzzing the study options: the error escaped as "cannot write the results" (exit 1).
    const ProcessResult unknown = runBeamrotor({"study", "problems/pump_rod.yaml", "--sample",
                                                "w0=lognormal(1e-3,abc)", "--samples", "3"});
    CHECK(unknown.exitCode == 2);
    CHECK(mentions(unknown.err, "--sample w0=lognormal(1e-3,abc): cannot evaluate 'abc'"));
    const ProcessResult unit = runBeamrotor({"study", "problems/pump_rod.yaml", "--sample",
                                             "w0=lognormal(1e-3,1 m)", "--samples", "3"});
    CHECK(unit.exitCode == 2);
    CHECK(mentions(unit.err, "sigma (of the logarithm) is a pure number, got '1 m'"));
  }
}

// A static solution whose measured round-off leaves no digit to trust fails its analysis
// (problems/run/UntrustedStatics.hpp): the 1.2 m cantilever of 20,000 and 50,000 elements,
// 95 % and 100 % off its closed form, exits 1 naming the estimate and the cheapest adequate
// mesh of the `accuracy:` search, which is checked against the closed form itself; with
// `accept_round_off: true` the result is kept (exit 0, the warning stays).
#include <doctest/doctest.h>

#include <cmath>
#include <fstream>
#include <numbers>
#include <sstream>

#include "tests/problems/DeckTestSupport.hpp"

using namespace beamrotor;
using namespace beamrotor::test;
namespace fs = std::filesystem;

namespace {

const fs::path kFixture = fs::path(BEAMROTOR_SOURCE_DIR) /
                          "tests/problems/over_refined/cantilever_4000.yaml";

/// The fixture (a tip-loaded cantilever, statics only) with `elements` elements and its
/// static analysis written as `analysis`.
std::string cantilever(int elements, const std::string& analysis = "{type: static}") {
  std::string text = fileContents(kFixture);
  const auto replace = [&](const std::string& from, const std::string& to) {
    REQUIRE(text.find(from) != std::string::npos);
    text.replace(text.find(from), from.size(), to);
  };
  replace("elements: 4000", "elements: " + std::to_string(elements));
  replace("- {type: static}", "- " + analysis);
  return text;
}

/// The closed-form tip deflection -P L^3 / (3 E I) of the fixture.
double exactTip() {
  const double L = 1.2, D = 0.05, P = 1000, E = 210e9;
  const double I = std::numbers::pi * std::pow(D, 4) / 64;
  return -P * L * L * L / (3 * E * I);
}

ProcessResult solveText(const fs::path& dir, const std::string& name, const std::string& text) {
  std::ofstream(dir / name) << text;
  return runBeamrotor({"solve", (dir / name).string(), "--out", (dir / "out").string()});
}

}  // namespace

TEST_SUITE("untrusted statics") {
  TEST_CASE("20,000 and 50,000 elements: exit 1 naming the estimate and the adequate mesh") {
    const fs::path dir = scratchDir("untrusted-statics");
    for (int elements : {20000, 50000}) {
      CAPTURE(elements);
      const ProcessResult p = solveText(dir, "fine.yaml", cantilever(elements));
      CAPTURE(p.err);
      CHECK(p.exitCode == 1);
      CHECK(p.err.find("fine.yaml:40:5: analyses[0]") != std::string::npos);
      CHECK(p.err.find("analyses[0]: the static solution's round-off error, bounded by "
                       "measurement at ") != std::string::npos);
      CHECK(p.err.find("leaves no digit to trust (" + std::to_string(elements) +
                       " beam elements)") != std::string::npos);
      // Hermite elements are exact for a tip load: two agree with one to round-off.
      CHECK(p.err.find("finds 2 elements per segment adequate") != std::string::npos);
      CHECK(p.err.find("accept_round_off: true") != std::string::npos);
      CHECK_FALSE(fs::exists(dir / "out"));
    }
    // The mesh named is adequate indeed: the closed form to the deck's 1e-9.
    const ProcessResult two = solveText(dir, "two.yaml", cantilever(2));
    REQUIRE(two.exitCode == 0);
    const auto results = nlohmann::json::parse(fileContents(dir / "out" / "results.json"));
    CHECK(results["analyses"][0]["displacements"]["tip"]["uy"].get<double>() ==
          doctest::Approx(exactTip()).epsilon(1e-9));
    fs::remove_all(dir);
  }

  TEST_CASE("accept_round_off: true keeps the untrusted result, which is as far off as said") {
    const fs::path dir = scratchDir("untrusted-statics-accepted");
    for (int elements : {20000, 50000}) {
      CAPTURE(elements);
      const ProcessResult p =
          solveText(dir, "fine.yaml", cantilever(elements, "{type: static, accept_round_off: true}"));
      CAPTURE(p.err);
      REQUIRE(p.exitCode == 0);
      CHECK(p.out.find("no digit of the solution can be trusted") != std::string::npos);
      const auto results = nlohmann::json::parse(fileContents(dir / "out" / "results.json"));
      const double tip = results["analyses"][0]["displacements"]["tip"]["uy"].get<double>();
      // 95 % and 100 % off the closed form: the refusal was right.
      CHECK(std::abs(tip - exactTip()) / std::abs(exactTip()) > 0.5);
      CHECK(results["analyses"][0]["round_off"].get<double>() >= 1);
    }
    fs::remove_all(dir);
  }

  TEST_CASE("where the accuracy: search cannot choose, the failure says why; bad values named") {
    const fs::path dir = scratchDir("untrusted-statics-nosearch");
    std::string unchecked = cantilever(20000);
    unchecked.erase(unchecked.find("checks:"));
    const ProcessResult p = solveText(dir, "unchecked.yaml", unchecked);
    CHECK(p.exitCode == 1);
    CHECK(p.err.find("the accuracy: search cannot choose a mesh here (it needs checks to "
                     "measure, and this deck has none)") != std::string::npos);
    const ProcessResult bad =
        solveText(dir, "bad.yaml", cantilever(16, "{type: static, accept_round_off: maybe}"));
    CHECK(bad.exitCode == 2);
    CHECK(bad.err.find("analyses[0].accept_round_off") != std::string::npos);
    fs::remove_all(dir);
  }
}

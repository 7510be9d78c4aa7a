// `beamrotor converge` end to end: its files, their layout, and bad options as one-line errors.
#include <doctest/doctest.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>

#include "tests/problems/DeckTestSupport.hpp"

namespace beamrotor {

TEST_SUITE("converge cli") {
  TEST_CASE("converge writes convergence.json, csv and both charts; errors fall at order 4") {
    const auto dir = test::scratchDir("converge_cli") / "out";
    const test::ProcessResult p = test::runBeamrotor(
        {"converge", "problems/simply_supported.yaml", "--levels", "4", "--out", dir.string()});
    REQUIRE_MESSAGE(p.exitCode == 0, p.err);
    for (const char* m : {"eb-consistent", "eb-lumped", "timoshenko", "timoshenko-linear-full",
                          "timoshenko-linear-reduced"})
      CHECK(std::filesystem::exists(dir / ("convergence_" + std::string(m) + ".csv")));
    for (const char* chart : {"convergence_dofs", "convergence_time"})
      CHECK(std::filesystem::exists(dir / (std::string(chart) + ".gp")));
    std::ifstream in(dir / "convergence.json");
    const nlohmann::json doc = nlohmann::json::parse(in);
    CHECK(doc["quantity"] == "frequency 1");
    CHECK(doc["reference_kind"] == "closed form");
    CHECK(doc["check"] == "first frequency");
    REQUIRE(doc["methods"].size() == 5);
    const nlohmann::json& eb = doc["methods"][0];
    CHECK(eb["name"] == "eb-consistent");
    // f1 = (pi/L)^2 sqrt(E I / (rho A)) / (2 pi) of the deck, written out independently.
    const double L = 2, E = 210e9, rho = 7850, h = 0.06;
    const double f1 = M_PI / (2 * L * L) * std::sqrt(E * h * h / 12 / rho);
    CHECK(eb["reference"].get<double>() == doctest::Approx(f1).epsilon(1e-14));
    const nlohmann::json& levels = eb["levels"];
    REQUIRE(levels.size() == 4);
    CHECK(levels[0]["elements"] == 8);
    CHECK(levels[3]["elements"] == 64);
    CHECK(levels[0]["order"].is_null());
    for (int k = 1; k < 4; ++k) {
      // 8 to 64 consistent-mass elements: errors 1.6e-5 to 4e-9, asymptotic (measured 4.00).
      CHECK(std::abs(levels[k]["order"].get<double>() - 4) < 0.3);
      CHECK(levels[k]["dofs"].get<int>() == 2 * levels[k - 1]["dofs"].get<int>());
      CHECK(levels[k]["time_s"]["total"].get<double>() > 0);
    }
    // Re-running replaces its own earlier output (convergence.json marks it as beamrotor's).
    CHECK(test::runBeamrotor({"converge", "problems/simply_supported.yaml", "--levels", "2",
                              "--out", dir.string()})
              .exitCode == 0);
    std::filesystem::remove_all(dir.parent_path());
  }

  TEST_CASE("a deck of mechanisms alone: nothing to refine, one line naming the deck, exit 2") {
    for (const char* deck : {"problems/snt32_drive.yaml", "problems/forme_shaft_two_dof.yaml"}) {
      CAPTURE(deck);
      const test::ProcessResult p = test::runBeamrotor({"converge", deck});
      CHECK(p.exitCode == 2);
      CHECK(p.err.rfind(std::string(deck) + ":", 0) == 0);
      CHECK(p.err.find("no mesh or time step to refine") != std::string::npos);
      CHECK(std::count(p.err.begin(), p.err.end(), '\n') == 1);
    }
  }

  TEST_CASE("bad converge options: one line naming the option, exit 2") {
    const test::ProcessResult levels =
        test::runBeamrotor({"converge", "problems/simply_supported.yaml", "--levels", "1"});
    CHECK(levels.exitCode == 2);
    CHECK(levels.err ==
          "problems/simply_supported.yaml: --levels: must be from 2 (3 to "
          "extrapolate without a closed form) to 16, got 1\n");
    const test::ProcessResult quantity = test::runBeamrotor(
        {"converge", "problems/simply_supported.yaml", "--quantity", "displacement nowhere uy"});
    CHECK(quantity.exitCode == 2);
    CHECK(quantity.err.find("--quantity: ") != std::string::npos);
    CHECK(std::count(quantity.err.begin(), quantity.err.end(), '\n') == 1);
  }
}

}  // namespace beamrotor

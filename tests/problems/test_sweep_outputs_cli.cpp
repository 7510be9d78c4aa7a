// The stroke sweep of the default deck end to end: checks that apply only at some values
// (`when:`) leave empty cells in sweep.csv instead of failing the write.
#include <doctest/doctest.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>

namespace fs = std::filesystem;

TEST_SUITE("command line") {
  TEST_CASE("pump rod stroke sweep writes sweep.json with the published end values") {
    const fs::path out = fs::temp_directory_path() / "beamrotor_sweep_cli";
    fs::remove_all(out);
    const std::string cmd = std::string(BEAMROTOR_EXE) + " solve " + BEAMROTOR_SOURCE_DIR +
                            "/problems/pump_rod.yaml --sweep eta=0:0.4:4 --out " + out.string() +
                            " > /dev/null 2>&1";
    REQUIRE(std::system(cmd.c_str()) == 0);
    std::ifstream in(out / "sweep.json");
    const nlohmann::json doc = nlohmann::json::parse(in);
    REQUIRE(doc.at("values").size() == 5);
    REQUIRE(fs::exists(out / "sweep.csv"));
    // Middle reaction at the stroke ends: published 7.46 kN (eta = 0) and 13.33 kN (0.4), to
    // half a unit of the last printed digit.
    const auto& runs = doc.at("runs");
    auto middle = [&](std::size_t i) {
      return std::abs(runs.at(i).at("analyses").at(0).at("reactions").at("middle").at("fy")
                          .get<double>());
    };
    CHECK(std::abs(middle(0) - 7460) <= 5);
    CHECK(std::abs(middle(4) - 13330) <= 5);
    fs::remove_all(out);
  }
}

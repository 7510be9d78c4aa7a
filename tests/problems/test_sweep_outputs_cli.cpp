// The stroke sweep of the default deck end to end: checks that apply only at some values
// (`when:`) leave empty cells in sweep.csv instead of failing the write. A rotor deck swept over
// its bearing stiffness keeps the rotor figures (critical speeds, log decrements, peak orbits).
#include <doctest/doctest.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <sstream>

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

  TEST_CASE("forme shaft rotor swept over its bearing stiffness keeps the rotor figures") {
    // The rigid limit (E = 2e17) on bearings C1 and C2 = C1 l1 / l2: every critical speed is
    // sqrt(stiffness / inertia) (bounce sqrt((C1 + C2) / m), conical sqrt(k_phi / (Jd -+ Jp)),
    // problems/scenes/README.md section 2), so 4x the stiffness doubles each one.
    const fs::path out = fs::temp_directory_path() / "beamrotor_rotor_sweep_cli";
    fs::remove_all(out);
    const std::string cmd = std::string(BEAMROTOR_EXE) + " solve " + BEAMROTOR_SOURCE_DIR +
                            "/problems/forme_shaft_rotor.yaml --set E=2e17 --sweep C1=5e7,2e8"
                            " --out " + out.string() + " > /dev/null 2>&1";
    REQUIRE(std::system(cmd.c_str()) == 0);
    std::ifstream in(out / "sweep.json");
    const nlohmann::json doc = nlohmann::json::parse(in);
    REQUIRE(doc.at("values").size() == 2);
    const auto analysis = [&](std::size_t run, const std::string& name) {
      for (const auto& a : doc.at("runs").at(run).at("analyses"))
        if (a.at("name") == name) return a;
      FAIL("no analysis " << name);
      return nlohmann::json();
    };
    const auto soft = analysis(0, "campbell"), stiff = analysis(1, "campbell");
    REQUIRE(soft.at("critical_speeds").size() == 4);
    REQUIRE(stiff.at("critical_speeds").size() == 4);
    for (std::size_t k = 0; k < 4; ++k) {
      CAPTURE(k);
      const double ratio = stiff.at("critical_speeds").at(k).at("rpm").get<double>() /
                           soft.at("critical_speeds").at(k).at("rpm").get<double>();
      // The bounce lines are flat, their crossings exact, and the stiff shaft bends by ~1e-7
      // of the rigid motion: 2e-6 (the deck's 1e-6 per value, twice). The conical crossings
      // are interpolated between speeds 500 rpm apart: the deck's 1e-5 per value, twice.
      CHECK(std::abs(ratio - 2) <= (k < 2 ? 4e-6 : 4e-5));
    }
    // Undamped (beta 0): a conservative rotor's modes neither grow nor decay, log decrement 0
    // up to the eigensolver's round-off.
    for (const auto& c : {soft, stiff})
      CHECK(std::abs(c.at("smallest_log_decrement").at("value").get<double>()) < 1e-8);
    // The unbalance analysis keeps each response point's peak orbit, not its curves.
    const auto response = analysis(0, "unbalance");
    for (const char* point : {"A", "G", "B", "gear"})
      CHECK(response.at("peaks").at(point).at("amplitude_m").get<double>() > 0);
    CHECK_FALSE(response.contains("response"));
    // The same figures as columns of sweep.csv, and a chart of each analysis over C1.
    std::ifstream csv(out / "sweep.csv");
    std::stringstream text;
    text << csv.rdbuf();
    for (const char* column : {"campbell.critical_speed_1", "campbell.critical_speed_4",
                               "campbell.smallest_log_decrement", "unbalance.G.peak"})
      CHECK(text.str().find(column) != std::string::npos);
    fs::remove_all(out);
  }
}

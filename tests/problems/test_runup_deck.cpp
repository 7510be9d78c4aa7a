// The run-up analysis through the deck path, on the shipped Jeffcott deck
// (problems/jeffcott_runup.yaml): the peak of the passage against the Runge-Kutta figure of its
// header reaches the summary, results.json, the CSV tables and the checks; bad input is refused
// naming the field.
#include <doctest/doctest.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <numbers>
#include <string>

#include <nlohmann/json.hpp>

#include "elements/TiltingPadBearing.hpp"
#include "tests/problems/DeckTestSupport.hpp"

using namespace beamrotor;

namespace {

/// A run-up entry on a small rotor with `extra` lines appended to it.
std::string deckWith(const std::string& extra) {
  return R"(model: {dimension: lateral}
materials: [{name: steel, E: 210e9, nu: 0.3, rho: 7850}]
sections: [{name: rod, shape: circle, D: 0.03}]
segments: [{length: 0.7, section: rod, elements: 4}]
points: [{name: mid, at: 0.35}]
supports: [{name: a, at: start, fix: [uy, uz]}, {name: b, at: end, fix: [uy, uz]}]
analyses:
  - type: run-up
    unbalance: [{at: mid, me: 1e-4}]
    response: [mid]
)" + extra;
}

}  // namespace

TEST_SUITE("rotor decks") {
  TEST_CASE("run-up on journal films driven by a motor: every output, the closed-form speed") {
    const test::SolvedDeck solved =
        test::solveShippedDeckToScratch("journal_runup.yaml", "journal-runup-deck");
    const nlohmann::json results = solved.json("results.json");
    const nlohmann::json runUp = test::analysisOfType(results, "run-up");
    REQUIRE(runUp.is_object());
    CHECK(runUp["speed_driven"] == true);
    CHECK(runUp["bearings"] == "nonlinear");
    // The motor against inertia and the films' drag with the journals at Ocvirk's equilibrium
    // (the header's RK4): 2801.79 rpm after 3 s; the unbalance's torque and the orbit leave 5e-5.
    CHECK(runUp["end_rpm"].get<double>() == doctest::Approx(2801.79).epsilon(1e-4));
    CHECK(runUp["end_film_torque"].get<double>() > 0.09);
    CHECK(runUp["polar_inertia"].get<double>() == doctest::Approx(0.1).epsilon(1e-15));
    REQUIRE(runUp["journals"].size() == 2);
    const double eps = runUp["journals"][0]["start_eccentricity"].get<double>();
    CHECK(eps > 0.6);  // Ocvirk's equilibrium at 1200 rpm: 0.70
    CHECK(runUp["journals"][0]["largest_eccentricity"].get<double>() < 1);
    CHECK(std::abs(runUp["energy"]["balance"].get<double>()) <
          1e-6 * runUp["energy"]["work"].get<double>());
    for (const auto& check : results["checks"]) CHECK(check["pass"] == true);
    CHECK(solved.process.out.find("journal 'left' on its film") != std::string::npos);
    CHECK(solved.process.out.find("speed driven by a torque") != std::string::npos);
    const auto history = test::csvCells(solved.dir / "films_runup_history.csv");
    for (const char* column :
         {"left_eccentricity", "right_y", "drive_torque", "film", "film_torque", "rub"})
      CHECK(test::csvColumn(history[0], column) >= 0);
    CHECK(std::filesystem::exists(solved.dir / "films_runup_journals.png"));
    std::filesystem::remove_all(solved.dir.parent_path());
  }

  TEST_CASE("run-up on tilting-pad films: every output, the pads' equilibrium at the start") {
    // The test deck tests/problems/tilting_pad_runup.yaml (its run is too long to ship): two
    // four-pad bearings acting by their films through the critical speed.
    const test::SolvedDeck solved = test::solveShippedDeckToScratch(
        "../tests/problems/tilting_pad_runup.yaml", "tilting-pad-runup-deck");
    const nlohmann::json results = solved.json("results.json");
    nlohmann::json runUp;
    for (const auto& a : results["analyses"])
      if (a["type"] == "run-up") runUp = a;
    REQUIRE(runUp.is_object());
    CHECK(runUp["bearings"] == "nonlinear");
    REQUIRE(runUp["journals"].size() == 2);
    // The journals start where the pads carry 98.1 N at 2000 rpm: the bearing's own equilibrium
    // (tiltingPadPoint, a second Newton on the same pads) to its tolerance.
    PlainJournal j{0.04, 0.02, 40e-6, 0.02, 98.1};
    TiltingPads pads;
    pads.count = 4;
    pads.arc = 80 * std::numbers::pi / 180;
    pads.preload = 0.3;
    const TiltingPadPoint p = tiltingPadPoint(j, pads, 2000 * std::numbers::pi / 30, {16, 4});
    for (const auto& journal : runUp["journals"]) {
      CHECK(journal["start_eccentricity"].get<double>() ==
            doctest::Approx(p.eccentricity).epsilon(1e-8));
      CHECK(journal["largest_eccentricity"].get<double>() < 1);
      CHECK(journal["largest_eccentricity"].get<double>() > p.eccentricity);
    }
    CHECK(runUp["end_film_torque"].get<double>() > 0);
    CHECK(std::abs(runUp["energy"]["balance"].get<double>()) <
          1e-6 * runUp["energy"]["work"].get<double>());
    for (const auto& check : results["checks"]) CHECK(check["pass"] == true);
    CHECK(solved.process.out.find("journal 'left' on its film") != std::string::npos);
    const auto history = test::csvCells(solved.dir / "pads_runup_history.csv");
    for (const char* column : {"left_eccentricity", "right_y", "film", "film_torque",
                               "left_pad1_tilt", "right_pad4_tilt"})
      CHECK(test::csvColumn(history[0], column) >= 0);
    // The pads' tilts (rad) start at the bearing's equilibrium tilts plus the steady orbit's
    // share: the journal's orbit is some 0.03 c, a tilt's share of order that over R.
    const std::size_t tilt = test::csvColumn(history[0], "left_pad1_tilt");
    CHECK(std::abs(std::stod(history[1][tilt]) - p.pads[0].tilt) <
          0.1 * j.clearance / (j.diameter / 2));
    // Each pad's tilt range in results.json and the summary: those of its history column.
    const auto& left = runUp["journals"][0];
    REQUIRE(left["pad_tilts"].size() == 4);
    const auto& pad1 = left["pad_tilts"][0];
    CHECK(pad1["name"] == "pad1_tilt");
    double low = std::stod(history[1][tilt]), high = low;
    for (std::size_t row = 1; row < history.size(); ++row) {
      low = std::min(low, std::stod(history[row][tilt]));
      high = std::max(high, std::stod(history[row][tilt]));
    }
    // The CSV's shortest round-trip digits read back to the same doubles.
    CHECK(pad1["start"].get<double>() == std::stod(history[1][tilt]));
    CHECK(pad1["min"].get<double>() == low);
    CHECK(pad1["max"].get<double>() == high);
    CHECK(low < high);
    CHECK(solved.process.out.find("pads' tilts over the run: pad1_tilt ") != std::string::npos);
    CHECK(std::filesystem::exists(solved.dir / "pads_runup_journals.png"));
    std::filesystem::remove_all(solved.dir.parent_path());
  }

  TEST_CASE("run-up charts in the user's units: journals over their clearance, the peak") {
    // The journals' chart divides the history's positions (in mm here) by the clearance: the
    // divisor must be c in mm, so that the plotted radius is the eccentricity column, and the
    // amplitude chart's key names the peak of results.json (SI) in mm.
    const auto out = test::scratchDir("journal-runup-mm") / "out";
    const test::ProcessResult run = test::runBeamrotor(
        {"solve", "problems/journal_runup.yaml", "--out", out.string(), "--units", "length=mm"});
    CAPTURE(run.err);
    REQUIRE(run.exitCode == 0);
    const std::string script = test::fileContents(out / "films_runup_journals.gp");
    const auto history = test::csvCells(out / "films_runup_history.csv");
    const std::size_t y = test::csvColumn(history[0], "left_y"),
                      z = test::csvColumn(history[0], "left_z"),
                      e = test::csvColumn(history[0], "left_eccentricity");
    const std::string using_ = "($" + std::to_string(y + 1) + "/";
    const std::size_t at = script.find(using_);
    REQUIRE(at != std::string::npos);
    const double divisor = std::stod(script.substr(at + using_.size()));
    CHECK(divisor == doctest::Approx(0.040).epsilon(1e-12));  // c = 40 um in mm
    for (std::size_t row = 2; row < history.size(); row += 97) {
      const double radius = std::hypot(std::stod(history[row][y]), std::stod(history[row][z]));
      CHECK(radius / divisor == doctest::Approx(std::stod(history[row][e])).epsilon(1e-12));
    }
    const nlohmann::json results = nlohmann::json::parse(test::fileContents(out / "results.json"));
    double peak = 0;
    for (const auto& a : results["analyses"])
      if (a["type"] == "run-up") peak = a["points"][0]["peak_amplitude"].get<double>();
    const std::string amplitude = test::fileContents(out / "films_runup.gp");
    const std::size_t key = amplitude.find("disk: peak ");
    REQUIRE(key != std::string::npos);
    // The key's number has 4 significant digits.
    CHECK(std::stod(amplitude.substr(key + 11)) == doctest::Approx(peak * 1e3).epsilon(1e-3));
    CHECK(amplitude.find(" mm at ", key) != std::string::npos);
    std::filesystem::remove_all(out.parent_path());
  }

  TEST_CASE("run-up deck: the passage's peak in every output, against Runge-Kutta") {
    const test::SolvedDeck solved =
        test::solveShippedDeckToScratch("jeffcott_runup.yaml", "runup-deck");
    const nlohmann::json results = solved.json("results.json");
    const nlohmann::json runUp = test::analysisOfType(results, "run-up");
    REQUIRE(runUp.is_object());
    const nlohmann::json& disk = runUp["points"][0];
    CHECK(disk["point"] == "disk");
    // The header's RK4 figures (20000 steps; 0.6956 mm in the revolution of mean speed
    // 2638.7 rpm); the average acceleration rule's period error is 5e-5 at this step.
    CHECK(disk["peak_amplitude"].get<double>() == doctest::Approx(0.6956e-3).epsilon(2e-3));
    CHECK(disk["speed_at_peak_rpm"].get<double>() == doctest::Approx(2638.7).epsilon(1e-3));
    CHECK(runUp["steps"] == 8604);
    for (const auto& check : results["checks"]) CHECK(check["pass"] == true);
    CHECK(solved.process.out.find("disk: peak amplitude") != std::string::npos);
    const auto rows = test::csvCells(solved.dir / "runup_runup.csv");
    REQUIRE(rows.size() > 30);  // header and one row per revolution (34 completed)
    const int amplitude = test::csvColumn(rows[0], "disk_amplitude");
    double largest = 0;
    for (std::size_t i = 1; i < rows.size(); ++i)
      largest = std::max(largest, std::stod(rows[i][amplitude]));
    CHECK(largest == doctest::Approx(disk["peak_amplitude"].get<double>()).epsilon(1e-6));
    const auto history = test::csvCells(solved.dir / "runup_runup_history.csv");
    CHECK(history.size() == 8604 / 2 + 2);  // header, t = 0 and every second step
    std::filesystem::remove_all(solved.dir.parent_path());
  }

  TEST_CASE("rub on a seal: the closed forms of the deck's header in every output") {
    const test::SolvedDeck solved =
        test::solveShippedDeckToScratch("jeffcott_rub.yaml", "jeffcott-rub-deck");
    const nlohmann::json results = solved.json("results.json");
    const nlohmann::json runUp = test::analysisOfType(results, "run-up");
    REQUIRE(runUp.is_object());
    REQUIRE(runUp["rubs"].size() == 1);
    const auto& seal = runUp["rubs"][0];
    // The header's closed forms: N = 70.594 N, mu N R = 0.211783 N m, 322.581 rpm at 0.3 s
    // (Newton's static equilibrium: 1e-8; the speed's trapezoid rule is exact for a constant
    // torque: the round-off of 300 steps).
    CHECK(seal["peak_normal_force"].get<double>() == doctest::Approx(70.5945).epsilon(1e-5));
    CHECK(seal["peak_rub_torque"].get<double>() == doctest::Approx(0.211783).epsilon(1e-5));
    CHECK(seal["contact_time"].get<double>() == doctest::Approx(0.3).epsilon(1e-12));
    CHECK(seal["first_contact"].get<double>() == 0.0);
    CHECK(runUp["end_rpm"].get<double>() == doctest::Approx(322.581).epsilon(1e-6));
    // The friction dissipates mu N R Omega: the torque times the angle turned.
    CHECK(seal["friction_work"].get<double>() ==
          doctest::Approx(0.211783 * (322.581 + 300) / 2 * 3.14159265358979 / 30 * 0.3)
              .epsilon(1e-5));
    for (const auto& check : results["checks"]) CHECK(check["pass"] == true);
    CHECK(solved.process.out.find("rub 'seal' (c = ") != std::string::npos);
    const auto history = test::csvCells(solved.dir / "rub_runup_history.csv");
    for (const char* column :
         {"seal_radial", "seal_normal_force", "seal_friction_force", "seal_rub_torque", "rub"})
      CHECK(test::csvColumn(history[0], column) >= 0);
    const std::string script = test::fileContents(solved.dir / "rub_runup_orbits.gp");
    CHECK(script.find("clearance of rub") != std::string::npos);
    CHECK(std::filesystem::exists(solved.dir / "rub_runup_orbits.png"));
    std::filesystem::remove_all(solved.dir.parent_path());
  }

  TEST_CASE("run-up: bad input is refused naming the field and its line") {
    struct Bad {
      std::string lines;
      int line;
      std::string says;
    };
    const std::vector<Bad> cases{
        {"    from_rpm: 0\n    to_rpm: 1000\n    duration: 1 s\n    dt: 1 m\n", 14, "dt"},
        {"    from_rpm: 500\n    to_rpm: 500\n    duration: 1 s\n    dt: 1 ms\n", 12, "to_rpm"},
        {"    speed_table: [[0, 0], [1 s, 100], [1 s, 200]]\n    dt: 1 ms\n", 11, "ascend"},
        {"    speed_table: [[0, 0], [1 s, 100]]\n    dt: 1 ms\n    alpha: -0.1\n", 13, "hht"},
        {"    speed_table: [[0, 0], [100 s, 100]]\n    dt: 1e-6 s\n", 12, "steps"},
        {"    from_rpm: 0\n    to_rpm: 100\n    duration: 1 s\n    dt: 1 ms\n    start: hot\n",
         15, "steady"},
        {"    from_rpm: 100\n    to_rpm: 200\n    duration: 1 s\n    dt: 1 ms\n"
         "    bearings: nonlinear\n",
         15, "type: plain-journal"},
        {"    from_rpm: 100\n    duration: 1 s\n    dt: 1 ms\n    speed: {torque: 5 kg}\n", 14,
         "moment"},
        {"    from_rpm: 100\n    to_rpm: 200\n    duration: 1 s\n    dt: 1 ms\n"
         "    speed: {torque: 5}\n",
         12, "torque"},
        {"    from_rpm: 100\n    to_rpm: 200\n    duration: 1 s\n    dt: 1 ms\n"
         "    rub: [{at: mid, clearance: 0.1 mm, stiffness: 1e7 N/m, friction: 0.2}]\n",
         15, "radius"},
        {"    from_rpm: 100\n    to_rpm: 200\n    duration: 1 s\n    dt: 1 ms\n"
         "    rub: [{at: mid, clearance: 0.1 kg, stiffness: 1e7, friction: 0.2, radius: 1 cm}]\n",
         15, "length"},
        {"    from_rpm: 100\n    to_rpm: 200\n    duration: 1 s\n    dt: 1 ms\n"
         "    rub: [{at: mid, clearance: 0.1 mm, stiffness: -1e7, friction: 0.2, radius: 1 cm}]\n",
         15, "positive"},
        {"    from_rpm: 100\n    to_rpm: 200\n    duration: 1 s\n    dt: 1 ms\n"
         "    rub: [{at: middle, clearance: 0.1 mm, stiffness: 1e7, friction: 0.2, radius: 1 cm}]\n",
         15, "middle"},
        {"    from_rpm: 100\n    to_rpm: 200\n    duration: 1 s\n    dt: 1 ms\n"
         "    rub: [{at: mid, clearance: 0.1 mm, stiffness: 1e7, friction: 0.2, radius: 1 cm,\n"
         "           slip: 1}]\n",
         16, "slip_velocity"},
    };
    for (const Bad& b : cases) {
      CAPTURE(b.lines);
      const DeckError e = test::readingError(deckWith(b.lines), "runup.yaml");
      CAPTURE(e.message());
      CHECK(e.place().line == b.line);
      CHECK(e.message().find(b.says) != std::string::npos);
    }
  }
}

// The chart defects of issue 43, each kind with a test that fails on it: labels and titles at
// full precision or showing round-off, curves clipped inside their data, two series in one
// style, a colour scale that does not span its data, an unstable speed range left unmarked, a
// line without its shear-force panel, and mode shapes "normalised to 1" that peak above 1.
// Each reads the chart's script and the table it draws, as a reader compares a chart with its
// CSV.
#include <doctest/doctest.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <functional>
#include <optional>
#include <sstream>
#include <limits>
#include <map>
#include <regex>
#include <set>
#include <string>
#include <vector>

#include "problems/output/files/ChartParts.hpp"
#include "tests/problems/DeckTestSupport.hpp"

namespace beamrotor {

namespace {

namespace fs = std::filesystem;

/// The single-quoted literals of a gnuplot script (its titles, labels and key entries), colours
/// ('#rrggbb') left out.
std::vector<std::string> literals(const std::string& script) {
  std::vector<std::string> out;
  const std::regex literal("'([^'\\n]*)'");
  for (auto it = std::sregex_iterator(script.begin(), script.end(), literal);
       it != std::sregex_iterator(); ++it)
    if ((*it)[1].str().rfind('#', 0) != 0) out.push_back((*it)[1].str());  // not a colour
  return out;
}

/// Numbers in a text printed with more significant digits than a reader needs (7 or more), or
/// round-off (an exponent below -12, a negative zero).
std::vector<std::string> overPrecise(const std::string& text) {
  std::vector<std::string> found;
  const std::regex number("-?[0-9]+(\\.[0-9]+)?(e[-+]?[0-9]+)?");
  for (auto it = std::sregex_iterator(text.begin(), text.end(), number);
       it != std::sregex_iterator(); ++it) {
    const std::string n = (*it)[0].str();
    std::string digits;
    for (char c : n.substr(0, n.find('e')))
      if (c >= '0' && c <= '9') digits += c;
    digits.erase(0, std::min(digits.find_first_not_of('0'), digits.size()));
    const bool roundOff = n == "-0" || std::regex_search(n, std::regex("e-(1[3-9]|[2-9][0-9])"));
    if (digits.size() >= 7 || roundOff) found.push_back(n);
  }
  return found;
}

/// The style of each titled curve of each `plot` command: the text between "with" and
/// "title", per plot.
std::vector<std::vector<std::string>> plotStyles(const std::string& script) {
  std::vector<std::vector<std::string>> plots;
  std::string joined;  // continuation lines joined
  for (std::size_t i = 0; i < script.size(); ++i)
    if (script.compare(i, 2, "\\\n") == 0)
      ++i;
    else
      joined += script[i];
  std::istringstream lines(joined);
  const std::regex curve(" with (.*?) title '");
  for (std::string line; std::getline(lines, line);) {
    const std::size_t at = line.find("plot ");
    if (at == std::string::npos || line.find_first_not_of(' ') != at) continue;
    std::vector<std::string> styles;
    for (auto it = std::sregex_iterator(line.begin(), line.end(), curve);
         it != std::sregex_iterator(); ++it)
      styles.push_back((*it)[1].str());
    plots.push_back(styles);
  }
  return plots;
}

/// A solved deck's results directory (charts as PNG).
fs::path solved(const std::string& deck, const std::vector<std::string>& options,
                const std::string& name) {
  const fs::path out = test::scratchDir("chart-defects-" + name) / "out";
  std::vector<std::string> arguments{"solve", deck, "--out", out.string()};
  arguments.insert(arguments.end(), options.begin(), options.end());
  const test::ProcessResult r = test::runBeamrotor(arguments);
  CAPTURE(r.err);
  REQUIRE(r.exitCode == 0);
  return out;
}

/// The numbers of a CSV column (empty cells skipped).
std::vector<double> columnValues(const fs::path& csv, const std::string& name) {
  const auto cells = test::csvCells(csv);
  REQUIRE_MESSAGE(!cells.empty(), csv.string());
  const std::size_t c = test::csvColumn(cells.front(), name);
  std::vector<double> values;
  for (std::size_t r = 1; r < cells.size(); ++r)
    if (c < cells[r].size() && !cells[r][c].empty()) values.push_back(std::stod(cells[r][c]));
  return values;
}

/// Every header cell of a CSV holding `part`.
std::vector<std::string> columnsWith(const fs::path& csv, const std::string& part) {
  std::vector<std::string> names;
  const auto cells = test::csvCells(csv);
  REQUIRE_MESSAGE(!cells.empty(), csv.string());
  for (std::string cell : cells.front()) {
    cell.erase(std::remove(cell.begin(), cell.end(), '"'), cell.end());
    if (cell.find(part) != std::string::npos) names.push_back(cell);
  }
  return names;
}

std::pair<double, double> rangeIn(const std::string& script, const std::string& command,
                                  std::size_t occurrence) {
  const std::regex range("set " + command + " \\[([-+0-9.e]+):([-+0-9.e]+)\\]");
  std::size_t k = 0;
  for (auto it = std::sregex_iterator(script.begin(), script.end(), range);
       it != std::sregex_iterator(); ++it, ++k)
    if (k == occurrence) return {std::stod((*it)[1].str()), std::stod((*it)[2].str())};
  FAIL("no set " << command << " number " << occurrence);
  return {0, 0};
}

}  // namespace

TEST_SUITE("chart defects") {
  TEST_CASE("the defect finders find the defects (they can fail)") {
    CHECK(overPrecise("n_op = 308.92327760299634") ==
          std::vector<std::string>{"308.92327760299634"});
    CHECK(overPrecise("ULS: 2.274e-16 kN m") == std::vector<std::string>{"2.274e-16"});
    CHECK(overPrecise("SLS: -0 kN m") == std::vector<std::string>{"-0"});
    CHECK(overPrecise("eta = 0.2 m, F = 1.25e+04 N, mode 1: 23.99 Hz").empty());
    const auto twoInOne = plotStyles(
        "  plot 'a' using 1:2 with lines lw 2 title 'A kxx', \\\n"
        "       'a' using 1:3 with lines lw 2 title 'B kxx'\n");
    REQUIRE(twoInOne.size() == 1);
    CHECK(twoInOne[0][0] == twoInOne[0][1]);
    // Round-off shown as zero, the rest to 4 significant digits.
    CHECK(labelNumber(2.274e-16, 1.5e3) == "0");
    CHECK(labelNumber(-0.0) == "0");
    CHECK(labelNumber(308.92327760299634) == "308.9");
  }

  TEST_CASE("titles and labels: no full precision, no round-off, no parameter dump") {
    // The rotor deck with a parameter set on the command line: the title names it, rounded;
    // the continuous beam's envelopes label their extremes, round-off among them.
    std::vector<fs::path> dirs{
        solved("problems/compressor_rotor.yaml", {"--set", "me=2.0000000001e-4"}, "titles"),
        solved("problems/continuous_beam.yaml", {}, "envelopes")};
    int scripts = 0;
    for (const fs::path& dir : dirs)
      for (const auto& entry : fs::directory_iterator(dir)) {
        if (entry.path().extension() != ".gp") continue;
        ++scripts;
        const std::string script = test::fileContents(entry.path());
        CAPTURE(entry.path().filename().string());
        CHECK(script.find("in SI units") == std::string::npos);
        for (const std::string& text : literals(script))
          for (const std::string& n : overPrecise(text)) FAIL_CHECK(text << ": " << n);
      }
    CHECK(scripts >= 8);
    const std::string map = test::fileContents(dirs[0] / "campbell_campbell.gp");
    CHECK(map.find("me = 0.0002") != std::string::npos);  // the set parameter, rounded
    fs::remove_all(dirs[0].parent_path());
    fs::remove_all(dirs[1].parent_path());
  }

  TEST_CASE("every plot draws its titled curves in styles of their own") {
    int plots = 0;
    for (const char* deck : {"compressor_rotor.yaml", "forme_shaft_rotor.yaml",
                             "pump_rod_hinged.yaml", "continuous_beam.yaml", "snt32_drive.yaml"}) {
      const fs::path dir = solved(std::string("problems/") + deck, {}, "styles");
      for (const auto& entry : fs::directory_iterator(dir)) {
        if (entry.path().extension() != ".gp") continue;
        CAPTURE(entry.path().filename().string());
        for (const auto& styles : plotStyles(test::fileContents(entry.path()))) {
          ++plots;
          const std::set<std::string> distinct(styles.begin(), styles.end());
          CHECK(distinct.size() == styles.size());
        }
      }
      fs::remove_all(dir.parent_path());
    }
    CHECK(plots >= 15);
  }

  TEST_CASE("stability chart: the colour scale spans the decrements, no curve is clipped") {
    const fs::path dir = solved("problems/compressor_rotor.yaml", {}, "stability");
    const std::string script = test::fileContents(dir / "campbell_stability.gp");
    double least = std::numeric_limits<double>::infinity(), most = -least;
    const fs::path campbell = dir / "campbell_campbell.csv";
    for (const std::string& column : columnsWith(campbell, "_log_decrement"))
      for (double d : columnValues(campbell, column))
        if (std::isfinite(d)) least = std::min(least, d), most = std::max(most, d);
    REQUIRE(least < most);
    const auto [cbLow, cbHigh] = rangeIn(script, "cbrange", 0);
    // The scale is the data's own range (to the 6 digits the script writes).
    CHECK(cbLow == doctest::Approx(least).epsilon(1e-5));
    CHECK(cbHigh == doctest::Approx(most).epsilon(1e-5));
    // The decrement panel (the one numeric y range: the Campbell panel's is [0:*]) holds every
    // finite decrement and zero.
    const auto [low, high] = rangeIn(script, "yrange", 0);
    CHECK(low <= std::min(least, 0.0));
    CHECK(high >= most);
    // No value is replaced by the axis' end (the old clamp to the top of the axis).
    CHECK(script.find(" > " + number(high) + " ? ") == std::string::npos);
    fs::remove_all(dir.parent_path());
  }

  TEST_CASE("unbalance chart: the unstable range marked, readable markers and axis") {
    const fs::path dir = solved("problems/compressor_rotor.yaml", {}, "unbalance");
    std::ifstream in(dir / "results.json");
    const nlohmann::json doc = nlohmann::json::parse(in);
    std::string unbalance;
    std::optional<double> onset;
    // The onset of instability the unbalance analysis' API 684 reading found, wherever it is.
    const std::function<void(const nlohmann::json&)> findOnset = [&](const nlohmann::json& j) {
      if (!j.is_object() && !j.is_array()) return;
      if (j.is_object() && j.contains("onset_rpm") && j["onset_rpm"].is_number())
        onset = j["onset_rpm"].get<double>();
      for (const auto& item : j) findOnset(item);
    };
    for (const auto& a : doc["analyses"])
      if (a["type"] == "unbalance") {
        unbalance = a["name"];
        findOnset(a);
      }
    REQUIRE(!unbalance.empty());
    const std::string script = test::fileContents(dir / (unbalance + "_unbalance.gp"));
    if (onset) {
      CHECK(script.find("unstable above " + labelNumber(*onset) + " rpm") != std::string::npos);
      CHECK(script.find("set object 90 rectangle from first " + number(*onset)) !=
            std::string::npos);
    }
    // A marker every few rows, not on each of the hundreds of rows.
    CHECK(script.find("pointinterval") != std::string::npos);
    // The amplitude axis spans at most four decades (and the one its ends round out to).
    const std::regex decades("set yrange \\[1e(-?[0-9]+):1e(-?[0-9]+)\\]");
    std::smatch m;
    REQUIRE(std::regex_search(script, m, decades));
    CHECK(std::stoi(m[2].str()) - std::stoi(m[1].str()) <= 5);
    fs::remove_all(dir.parent_path());
  }

  TEST_CASE("the diagrams along a line have a shear-force panel") {
    const fs::path dir = solved("problems/cantilever.yaml", {}, "shear-force");
    const std::string script = test::fileContents(dir / "static_diagrams.gp");
    CHECK(script.find("shear force [kN]") != std::string::npos);
    // The panel plots Vy: the cantilever's is P = 1 kN along the whole length.
    const auto vy = columnValues(dir / "static_fields.csv", "Vy");
    REQUIRE(!vy.empty());
    for (double v : vy) CHECK(std::abs(std::abs(v) - 1000) < 1e-6);
    fs::remove_all(dir.parent_path());
  }

  TEST_CASE("mode shapes normalised to largest translation 1 peak at exactly 1") {
    // Three elements on a simply supported span: the nodes at L/3 and 2L/3 carry the first
    // mode's largest nodal value, and the cubic between them bulges past it (about 1.15).
    const fs::path dir = test::scratchDir("chart-defects-shapes");
    std::ofstream(dir / "coarse.yaml")
        << "materials: [{name: steel, E: 210 GPa, nu: 0.3, rho: 7850 kg/m^3}]\n"
           "sections: [{name: bar, shape: rectangle, b: 40 mm, h: 60 mm}]\n"
           "segments: [{length: 2 m, section: bar, elements: 3}]\n"
           "supports:\n  - {name: left, at: start, fix: [ux, uy]}\n"
           "  - {name: right, at: end, fix: [uy]}\n"
           "analyses: [{type: modal, modes: 2}]\n";
    const test::ProcessResult r =
        test::runBeamrotor({"solve", "coarse.yaml", "--out", "out"}, dir);
    REQUIRE_MESSAGE(r.exitCode == 0, r.err);
    const fs::path shapes = dir / "out" / "modal_shapes.csv";
    for (const char* mode : {"mode1_uy", "mode2_uy"}) {
      CAPTURE(mode);
      double largest = 0;
      for (double v : columnValues(shapes, mode)) largest = std::max(largest, std::abs(v));
      CHECK(largest == doctest::Approx(1).epsilon(1e-12));
    }
    CHECK(test::fileContents(dir / "out" / "modal_shapes.gp").find("largest translation = 1") !=
          std::string::npos);
    fs::remove_all(dir);
  }
}

}  // namespace beamrotor

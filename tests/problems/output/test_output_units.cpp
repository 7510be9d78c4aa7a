// Output units (issue 43): `output: units:` and `--units` set the units of the summary, the
// CSV tables and the charts; results.json stays SI. The references are the SI results of the
// same run (a unit conversion is a multiplication by an exact factor: 1000 is exact in binary
// floating point, so a length in mm is the SI value times 1000 to the last bit) and the closed
// forms of the cantilever.
#include <doctest/doctest.h>

#include <algorithm>
#include <cmath>
#include <iomanip>
#include <map>
#include <numbers>
#include <sstream>
#include <string>

#include "problems/deck/OutputUnits.hpp"
#include "problems/deck/parse/UnitText.hpp"
#include "problems/output/Output.hpp"
#include "problems/output/PreparedRun.hpp"
#include "problems/output/files/ChartParts.hpp"
#include "problems/output/files/TableUnits.hpp"
#include "tests/problems/DeckTestSupport.hpp"
#include "tests/problems/output/OutputFixtures.hpp"

using namespace beamrotor;
using namespace beamrotor::test;
namespace fs = std::filesystem;

namespace {

OutputUnits unitsOf(const std::string& list) { return parseOutputUnits(list); }

/// The message set() throws for quantity = unit.
std::string setError(const std::string& quantity, const std::string& unit) {
  OutputUnits units;
  try {
    units.set(quantity, unit);
  } catch (const std::invalid_argument& e) {
    return e.what();
  }
  return "";
}

/// The column `name` of a prepared run's analysis `a`, table `file`.
const CsvTable& tableOf(const PreparedRun& p, std::size_t a, const std::string& file) {
  for (const auto& [name, table] : p.analyses.at(a).tables())
    if (name == file) return *table;
  throw std::out_of_range("no table " + file);
}

std::string unitOf(const CsvTable& t, const std::string& column) {
  return t.columns().at(std::size_t(t.column(column) - 1)).unit;
}

/// Rows of a CSV file beamrotor wrote, the units line kept apart.
struct WrittenCsv {
  std::vector<std::vector<std::string>> rows;  ///< header first
  std::string unitsLine;
};

WrittenCsv writtenCsv(const fs::path& file) {
  WrittenCsv out;
  std::istringstream in(fileContents(file));
  for (std::string line; std::getline(in, line);) {
    if (line.rfind("# units:", 0) == 0) {
      out.unitsLine = line;
      continue;
    }
    std::vector<std::string> cells;
    std::istringstream s(line);
    for (std::string cell; std::getline(s, cell, ',');) cells.push_back(cell);
    out.rows.push_back(cells);
  }
  return out;
}

}  // namespace

TEST_SUITE("output units") {
  TEST_CASE("a unit text is the deck's units multiplied and divided") {
    const auto kNm = unitSize("kN m");
    REQUIRE(kNm);
    CHECK(kNm->si == 1000);
    CHECK(kNm->dimension == dim::moment);
    CHECK(unitSize("N s/m")->dimension == dim::damping);
    CHECK(unitSize("m/s^2")->dimension == dim::acceleration);
    CHECK(unitSize("m/(rad s)")->dimension == Dimension::of(1, 0, -1, -1));
    CHECK(unitSize("1/s")->dimension == dim::frequency);
    CHECK(unitSize("rpm")->si == doctest::Approx(2 * std::numbers::pi / 60).epsilon(1e-15));
    CHECK_FALSE(unitSize("furlong"));
    CHECK_FALSE(unitSize("%"));
    CHECK_FALSE(unitSize("m/s/s"));  // two readings: refused
  }

  TEST_CASE("each quantity in a unit of its dimension; compounds follow their parts") {
    const OutputUnits mm = unitsOf("length=mm");
    CHECK(mm.of("m").factor == 1000);
    CHECK(mm.of("m").unit == "mm");
    CHECK(mm.of("N").factor == 1);  // force not set: as it is
    CHECK(mm.of("N").unit == "N");
    CHECK(mm.of("").unit.empty());

    const OutputUnits kN = unitsOf("force = kN");
    CHECK(kN.of("N m").unit == "kN m");
    CHECK(kN.of("N m").factor == doctest::Approx(1e-3).epsilon(1e-15));
    CHECK(kN.of("N/m").unit == "kN/m");
    CHECK(kN.of("N s/m").unit == "kN s/m");
    CHECK(kN.of("m/N").unit == "m/kN");
    CHECK(kN.of("m/N").factor == doctest::Approx(1e3).epsilon(1e-15));

    // A moment follows force length unless set itself.
    CHECK(unitsOf("force=kN,length=mm").of("N m").unit == "kN mm");
    CHECK(unitsOf("force=kN,length=mm").of("N m").factor == doctest::Approx(1).epsilon(1e-15));
    const OutputUnits kept = unitsOf("force=kN,length=mm,moment=kN m");
    CHECK(kept.of("N m").unit == "kN m");
    CHECK(kept.of("N m").factor == doctest::Approx(1e-3).epsilon(1e-15));

    // A speed in Hz is turns per second; a frequency in rpm cycles per minute.
    const OutputUnits hz = unitsOf("speed=Hz");
    CHECK(hz.of("rpm").factor == doctest::Approx(1.0 / 60).epsilon(1e-15));
    CHECK(hz.of("rad/s").factor == doctest::Approx(1 / (2 * std::numbers::pi)).epsilon(1e-15));
    CHECK(hz.of("Hz").factor == 1);  // a frequency column is no speed
    CHECK(unitsOf("frequency=rpm").of("Hz").factor == doctest::Approx(60).epsilon(1e-15));
    CHECK(unitsOf("angle=deg").of("rad").factor ==
          doctest::Approx(180 / std::numbers::pi).epsilon(1e-15));

    // A writer's own choice stays where the user set nothing.
    CHECK(mm.valueIn("Pa", {1e-6, "MPa"}).unit == "MPa");
    CHECK(mm.columnIn("m", {1e3, "mm"}).factor == 1);  // the table already holds mm
    CHECK(OutputUnits().columnIn("m", {1e3, "mm"}).factor == 1e3);
    CHECK(unitsOf("length=m").valueIn("m", {1e3, "mm"}).unit == "m");  // set to m: shown in m

    // The command line's units over the deck's, quantity by quantity.
    const OutputUnits both = unitsOf("length=mm,force=kN").overlaid(unitsOf("length=cm"));
    CHECK(both.of("m").unit == "cm");
    CHECK(both.of("N").unit == "kN");
  }

  TEST_CASE("a unit of the wrong dimension, an unknown unit or quantity: what is wrong") {
    CHECK(setError("length", "kN") ==
          "'kN' is a force (N), not a length (m); length takes m, km, cm, mm, um, in, ft");
    CHECK(setError("length", "furlong") ==
          "'furlong' is no unit; length takes m, km, cm, mm, um, in, ft");
    CHECK(setError("speed", "m/s") ==
          "'m/s' is a velocity (m/s), not an angular speed (rad/s); speed takes rpm, rad/s, Hz");
    CHECK(setError("lenght", "mm").find("did you mean 'length'") != std::string::npos);
    CHECK(setError("moment", "kN") ==
          "'kN' is a force (N), not a moment (N m); moment takes a moment (N m) written as a "
          "product of units, e.g. 'N m'");
    CHECK_THROWS_WITH_AS(parseOutputUnits("length"),
                         "'length' is no QUANTITY=UNIT (e.g. length=mm,force=kN)",
                         std::invalid_argument);
  }

  TEST_CASE("a cantilever's tables in mm and kN: the SI values times the exact factors") {
    const Cantilever c;
    const RunResult run = cantileverRun(c);
    const PreparedRun si = prepareRun(run);
    OutputChoices inMmAndKn;
    inMmAndKn.units = unitsOf("length=mm,force=kN");
    const PreparedRun shown = prepareRun(run, inMmAndKn);
    const CsvTable& a = tableOf(si, 0, "tip_fields.csv");
    const CsvTable& b = tableOf(shown, 0, "tip_fields.csv");
    CHECK(unitOf(b, "x") == "mm");
    CHECK(unitOf(b, "uy") == "mm");
    CHECK(unitOf(b, "rz") == "rad");  // angle not set
    CHECK(unitOf(b, "Vy") == "kN");
    CHECK(unitOf(b, "Mz") == "kN mm");
    CHECK(unitOf(b, "stress_top") == "Pa");  // stress not set
    const auto uySI = a.numbers("uy"), uyMm = b.numbers("uy");
    const auto mzSI = a.numbers("Mz"), mzShown = b.numbers("Mz");
    REQUIRE(uySI.size() == uyMm.size());
    for (std::size_t i = 0; i < uySI.size(); ++i) {
      CHECK(uyMm[i] == uySI[i] * 1000);  // 1000 exactly: bit for bit
      // N m -> kN mm: a factor of 1 reached through 1e-3 * 1e3 in floating point.
      CHECK(mzShown[i] == doctest::Approx(mzSI[i]).epsilon(1e-15));
    }
    // The tip against P L^3 / (3 EI): Hermite elements are exact at the nodes (round-off).
    CHECK(uyMm.back() == doctest::Approx(1000 * c.deflection(c.L)).epsilon(1e-9));
    CHECK(uyMm.back() == doctest::Approx(-1000 * c.P * std::pow(c.L, 3) / (3 * c.EI())).epsilon(1e-9));
    // The reactions table: its force and moment columns too (the root holds P and P L; N m
    // and kN mm are the same size).
    const CsvTable& ra = tableOf(si, 0, "tip_reactions.csv");
    const CsvTable& rb = tableOf(shown, 0, "tip_reactions.csv");
    CHECK(unitOf(rb, "force") == "kN");
    CHECK(unitOf(rb, "moment") == "kN mm");
    const auto forceSI = ra.numbers("force"), forceKn = rb.numbers("force");
    const auto momentSI = ra.numbers("moment"), momentShown = rb.numbers("moment");
    REQUIRE(forceSI.size() == forceKn.size());
    bool loaded = false;
    for (std::size_t i = 0; i < forceSI.size(); ++i) {
      if (std::isnan(forceSI[i])) continue;  // a moment's row
      CHECK(forceKn[i] == doctest::Approx(forceSI[i] / 1000).epsilon(1e-15));
      loaded = loaded || std::abs(std::abs(forceKn[i]) - c.P / 1000) < 1e-9;
    }
    CHECK(loaded);
    for (std::size_t i = 0; i < momentSI.size(); ++i)
      if (!std::isnan(momentSI[i]))
        CHECK(std::abs(momentShown[i]) == doctest::Approx(c.P * c.L).epsilon(1e-9));
    // results.json stays SI: the same document either way.
    CHECK(shown.results.doc.dump() == si.results.doc.dump());
  }

  TEST_CASE("written: the units line names the user's units; the charts draw in them") {
    const RecordedCharts recorded;
    const RunResult run = cantileverRun(Cantilever{});
    OutputChoices choices;
    choices.units = unitsOf("length=mm,force=kN,moment=kN m,stress=kPa");
    const fs::path dir = recorded.dir / "units";
    writeRunOutputs(run, dir, choices);
    const WrittenCsv fields = writtenCsv(dir / "tip_fields.csv");
    REQUIRE(fields.rows.size() > 2);
    const std::size_t uy = csvColumn(fields.rows[0], "uy");
    CHECK(fields.unitsLine.rfind("# units: mm,mm,mm,mm,rad,rad,rad,kN,kN,kN,kN m,kN m,kN m,kPa", 0) ==
          0);
    const Cantilever c;
    CHECK(std::stod(fields.rows.back()[uy]) ==
          doctest::Approx(1000 * c.deflection(c.L)).epsilon(1e-9));

    // The diagrams: axes in the user's units, the table's numbers drawn as they are (x 1).
    const std::string script = readText(dir / "tip_diagrams.gp");
    CHECK(script.find("set ylabel 'deflection [mm]'") != std::string::npos);
    CHECK(script.find("set ylabel 'bending moment [kN m]'") != std::string::npos);
    CHECK(script.find("set ylabel 'normal stress [kPa]'") != std::string::npos);
    CHECK(script.find("set ylabel 'shear force [kN]'") != std::string::npos);
    CHECK(script.find("set ylabel 'rotation [mrad]'") != std::string::npos);  // angle not set
    CHECK(script.find("set xlabel 'x along the line [mm]'") != std::string::npos);
    const std::string uyColumn = std::to_string(uy + 1);
    CHECK(script.find(":($" + uyColumn + "*1)") != std::string::npos);

    // Without output units the chart keeps its own reading units over the SI table.
    const fs::path plain = recorded.dir / "plain";
    writeRunOutputs(run, plain, OutputChoices{});
    const std::string own = readText(plain / "tip_diagrams.gp");
    CHECK(own.find("set ylabel 'deflection [mm]'") != std::string::npos);
    CHECK(own.find(":($" + uyColumn + "*1000)") != std::string::npos);
    CHECK(own.find("set xlabel 'x along the line [m]'") != std::string::npos);
    CHECK(writtenCsv(plain / "tip_fields.csv").unitsLine.rfind("# units: m,m,m,m,rad", 0) == 0);
  }

  TEST_CASE("a deck's output units: read, and refused naming file, line and field") {
    const std::string deck = fileContents(problemsDir() / "cantilever.yaml");
    const int lines = int(std::count(deck.begin(), deck.end(), '\n'));
    const DeckError wrong =
        readingError(deck + "output:\n  units:\n    force: kN\n    length: kN\n", "units.yaml");
    CHECK(wrong.place().field == "output.units.length");
    CHECK(wrong.place().line == lines + 4);
    CHECK(wrong.message() ==
          "'kN' is a force (N), not a length (m); length takes m, km, cm, mm, um, in, ft");
    const DeckError unknown = readingError(deck + "output:\n  units: {lenght: mm}\n", "units.yaml");
    CHECK(std::string(unknown.what()).find("did you mean 'length'") != std::string::npos);
    CHECK(unknown.place().line == lines + 2);
  }
}

TEST_SUITE("output units (command line)") {
  TEST_CASE("--units: summary, tables and results.json of the cantilever deck") {
    const fs::path dir = scratchDir("units-cantilever");
    const ProcessResult p =
        runBeamrotor({"solve", "problems/cantilever.yaml", "--out", (dir / "out").string(),
                      "--charts", "none", "--units", "length=mm,force=kN,moment=kN m"});
    REQUIRE_MESSAGE(p.exitCode == 0, p.err);
    // P = 1 kN at L = 1.2 m: the root carries fy 1 kN and mz 1.2 kN m (exact to round-off,
    // printed to six digits).
    CHECK(p.out.find("reactions (force on the structure; kN, kN m)") != std::string::npos);
    CHECK(p.out.find("fy 1 kN") != std::string::npos);
    CHECK(p.out.find("mz 1.2 kN m") != std::string::npos);
    CHECK(p.out.find("displacements at points (mm, rad)") != std::string::npos);
    CHECK(p.out.find("x = 1200 mm") != std::string::npos);
    const nlohmann::json results = readJson(dir / "out" / "results.json");
    const double tipSI = results["analyses"][0]["displacements"]["tip"]["uy"].get<double>();
    // E = 210 GPa, D = 50 mm: P L^3 / (3 E I) = 8.94025 mm (the deck's own check, 1e-9).
    const double I = std::numbers::pi * std::pow(0.05, 4) / 64;
    CHECK(tipSI == doctest::Approx(-1000.0 * std::pow(1.2, 3) / (3 * 210e9 * I)).epsilon(1e-9));
    std::ostringstream tip;
    tip << "uy " << std::setprecision(6) << tipSI * 1000 << " mm";
    CHECK(p.out.find(tip.str()) != std::string::npos);
    std::string stem;
    for (const auto& e : fs::directory_iterator(dir / "out"))
      if (e.path().filename().string().ends_with("_fields.csv")) stem = e.path().filename().string();
    REQUIRE_FALSE(stem.empty());
    const WrittenCsv fields = writtenCsv(dir / "out" / stem);
    CHECK(std::stod(fields.rows.back()[csvColumn(fields.rows[0], "uy")]) == tipSI * 1000);
    CHECK(fields.unitsLine.find("kN m") != std::string::npos);
    fs::remove_all(dir);
  }

  TEST_CASE("--units refused: a unit of the wrong dimension exits 2 naming the option") {
    const ProcessResult p =
        runBeamrotor({"solve", "problems/cantilever.yaml", "--units", "length=kN"});
    CHECK(p.exitCode == 2);
    CHECK(p.err.find("--units") != std::string::npos);
    CHECK(p.err.find("'kN' is a force (N), not a length (m)") != std::string::npos);
  }
}

// The places that printed SI whatever the units said: the check table, a sweep's parameter
// column and check columns, overlay and converge charts, the crank-slider and the torsion
// train. Each is compared with the same number in SI (results.json, which stays SI, or the
// deck's closed form) times the unit's exact factor, and its unit named where it is shown.
namespace {

/// "8.94025": v as the summary prints it (six significant digits).
std::string six(double v) {
  std::ostringstream s;
  s << std::setprecision(6) << v;
  return s.str();
}

/// The line of `text` that contains `what` ("" when none).
std::string lineWith(const std::string& text, const std::string& what) {
  std::istringstream in(text);
  for (std::string line; std::getline(in, line);)
    if (line.find(what) != std::string::npos) return line;
  return "";
}

/// The cantilever's tip deflection, -P L^3 / (3 E I) in m: P = 1 kN, E = 210 GPa, D = 50 mm.
double cantileverTip(double L) {
  const double I = std::numbers::pi * std::pow(0.05, 4) / 64;
  return -1000.0 * std::pow(L, 3) / (3 * 210e9 * I);
}

/// The number in `cells[column]` of the data row whose first cell is `first`.
double cellAt(const WrittenCsv& csv, std::size_t row, const std::string& column) {
  return std::stod(csv.rows.at(row).at(csvColumn(csv.rows.at(0), column)));
}

/// The units line's entry of `column`.
std::string unitEntry(const WrittenCsv& csv, const std::string& column) {
  std::vector<std::string> units;
  std::istringstream s(csv.unitsLine.substr(std::string("# units: ").size()));
  for (std::string u; std::getline(s, u, ',');) units.push_back(u);
  units.resize(csv.rows.at(0).size());
  return units.at(csvColumn(csv.rows.at(0), column));
}

}  // namespace

TEST_SUITE("output units (every place)") {
  TEST_CASE("beamrotor check: values, references and zero-reference tolerances in the units") {
    const ProcessResult mm = runBeamrotor(
        {"check", "problems/cantilever.yaml", "--units", "length=mm,force=kN"});
    REQUIRE_MESSAGE(mm.exitCode == 0, mm.err);
    // Computed and reference both -P L^3/(3 E I): the reference is the closed form itself.
    const std::string tip = lineWith(mm.out, "tip deflection");
    CHECK(tip.find(" " + six(1000 * cantileverTip(1.2)) + " mm") != std::string::npos);
    CHECK(tip.find("ref " + six(1000 * cantileverTip(1.2)) + " mm") != std::string::npos);
    // P L = 1.2 kN m = 1200 kN mm (a moment follows force and length).
    CHECK(lineWith(mm.out, "root moment").find("ref 1200 kN mm") != std::string::npos);
    CHECK(lineWith(mm.out, "root force").find("ref 1 kN") != std::string::npos);
    // The parameters line: the deck's L = 1.2 m, D = 50 mm, P = 1 kN.
    CHECK(mm.out.find("parameters: L = 1200 mm, D = 50 mm, P = 1 kN,") != std::string::npos);
    // Unset: the check's own unit, named.
    const ProcessResult si = runBeamrotor({"check", "problems/cantilever.yaml"});
    REQUIRE_MESSAGE(si.exitCode == 0, si.err);
    CHECK(lineWith(si.out, "tip deflection").find("ref " + six(cantileverTip(1.2)) + " m ") !=
          std::string::npos);
    CHECK(lineWith(si.out, "root moment").find("ref 1200 N m") != std::string::npos);
    CHECK(si.out.find("parameters: L = 1.2 m, D = 0.05 m, P = 1000 N,") != std::string::npos);
    // A wrong unit is an input error naming the option.
    const ProcessResult bad =
        runBeamrotor({"check", "problems/cantilever.yaml", "--units", "length=kN"});
    CHECK(bad.exitCode == 2);
    CHECK(bad.err.find("--units") != std::string::npos);
  }

  TEST_CASE("a sweep: the summary's parameter column and sweep.csv's check columns") {
    const fs::path dir = scratchDir("units-sweep");
    const ProcessResult p = runBeamrotor(
        {"solve", "problems/cantilever.yaml", "--sweep", "L=1m,1.2m", "--charts", "none",
         "--units", "length=mm", "--out", (dir / "out").string()});
    REQUIRE_MESSAGE(p.exitCode == 0, p.err);
    CHECK(p.out.find("at L = 1000 mm") != std::string::npos);
    const std::string header = lineWith(p.out, "L mm");
    REQUIRE_FALSE(header.empty());
    CHECK(p.out.find("\n  1200 ") != std::string::npos);  // 1.2 m x 1000
    const WrittenCsv sweep = writtenCsv(dir / "out" / "sweep.csv");
    REQUIRE(sweep.rows.size() == 3);
    CHECK(unitEntry(sweep, "L") == "mm");
    CHECK(unitEntry(sweep, "check.tip deflection") == "mm");
    CHECK(unitEntry(sweep, "check.tip rotation") == "rad");  // angle not set
    CHECK(cellAt(sweep, 2, "L") == 1200);
    // Hermite elements are exact at the nodes: the closed form to round-off (1e-9 as the deck).
    for (const auto& [row, L] : {std::pair{1, 1.0}, std::pair{2, 1.2}})
      CHECK(cellAt(sweep, std::size_t(row), "check.tip deflection") ==
            doctest::Approx(1000 * cantileverTip(L)).epsilon(1e-9));
    // sweep.json stays SI and names the check's unit.
    const nlohmann::json doc = readJson(dir / "out" / "sweep.json");
    const nlohmann::json& check = doc["runs"][1]["checks"][0];
    CHECK(check["unit"] == "m");
    fs::remove_all(dir);
  }

  TEST_CASE("beamrotor overlay: tables and chart in the units") {
    const fs::path dir = scratchDir("units-overlay");
    const ProcessResult p = runBeamrotor(
        {"overlay", "problems/cantilever.yaml", "problems/simply_supported.yaml", "--units",
         "length=mm,force=kN", "--out", (dir / "out").string()});
    REQUIRE_MESSAGE(p.exitCode == 0, p.err);
    const WrittenCsv fields = writtenCsv(dir / "out" / "cantilever_fields.csv");
    CHECK(unitEntry(fields, "uy") == "mm");
    CHECK(unitEntry(fields, "x") == "mm");
    CHECK(cellAt(fields, fields.rows.size() - 1, "uy") ==
          doctest::Approx(1000 * cantileverTip(1.2)).epsilon(1e-9));
    const std::string script = readText(dir / "out" / "overlay.gp");
    CHECK(script.find("set ylabel 'deflection [mm]'") != std::string::npos);
    CHECK(script.find("set ylabel 'shear force [kN]'") != std::string::npos);
    CHECK(script.find("set xlabel 'x along the line [mm]'") != std::string::npos);
    fs::remove_all(dir);
  }

  TEST_CASE("beamrotor converge: values, the value column and the time axis in the units") {
    const fs::path dir = scratchDir("units-converge");
    const ProcessResult p = runBeamrotor(
        {"converge", "problems/cantilever.yaml", "--quantity", "displacement tip uy", "--levels",
         "2", "--units", "length=mm,time=ms", "--out", (dir / "out").string()});
    REQUIRE_MESSAGE(p.exitCode == 0, p.err);
    const nlohmann::json doc = readJson(dir / "out" / "convergence.json");
    const nlohmann::json& method = doc["methods"][0];
    const std::string file = "convergence_" + method["name"].get<std::string>() + ".csv";
    const WrittenCsv table = writtenCsv(dir / "out" / file);
    CHECK(unitEntry(table, "value") == "mm");
    CHECK(unitEntry(table, "total") == "ms");
    const nlohmann::json& level = method["levels"][0];
    CHECK(cellAt(table, 1, "value") ==
          doctest::Approx(level["value"].get<double>() * 1000).epsilon(1e-15));
    CHECK(cellAt(table, 1, "value") == doctest::Approx(1000 * cantileverTip(1.2)).epsilon(1e-9));
    CHECK(cellAt(table, 1, "total") ==
          doctest::Approx(level["time_s"]["total"].get<double>() * 1000).epsilon(1e-15));
    CHECK(readText(dir / "out" / "convergence_time.gp").find("wall time (total) [ms]") !=
          std::string::npos);
    CHECK(p.out.find("value " + six(1000 * cantileverTip(1.2)).substr(0, 6)) !=
          std::string::npos);
    CHECK(lineWith(p.out, "level 0").find(" mm ") != std::string::npos);
    fs::remove_all(dir);
  }

  TEST_CASE("crank-slider: summary, motion table and charts in the units") {
    const fs::path dir = scratchDir("units-crank");
    const ProcessResult si = runBeamrotor(
        {"solve", "problems/snt32_drive.yaml", "--out", (dir / "si").string()});
    const ProcessResult p = runBeamrotor(
        {"solve", "problems/snt32_drive.yaml", "--units", "length=mm,force=kN,speed=rad/s",
         "--out", (dir / "out").string()});
    REQUIRE_MESSAGE(si.exitCode == 0, si.err);
    REQUIRE_MESSAGE(p.exitCode == 0, p.err);
    // The deck's r = 18.8 mm and l = 288 mm.
    CHECK(p.out.find("r = 18.8 mm, l = 288 mm") != std::string::npos);
    CHECK(si.out.find("r = 0.0188 m, l = 0.288 m") != std::string::npos);
    const nlohmann::json doc = readJson(dir / "out" / "results.json");
    const nlohmann::json& crank = doc["analyses"][0];  // 'drive', printed first
    REQUIRE(crank["name"] == "drive");
    const double rpm = crank["speed_rpm"].get<double>();
    CHECK(p.out.find(six(rpm * std::numbers::pi / 30) + " rad/s, ") != std::string::npos);
    // One crank's first harmonic m_rec r w^2 in kN: the SI summary's newtons / 1000.
    const std::string harmonic = lineWith(si.out, "inertia force, one crank");
    const double newtons = std::stod(harmonic.substr(harmonic.find("1st harmonic ") + 13));
    CHECK(lineWith(p.out, "inertia force, one crank").find(six(newtons / 1000) + " kN") !=
          std::string::npos);
    const std::string motion = "drive_motion.csv";
    const WrittenCsv a = writtenCsv(dir / "si" / motion), b = writtenCsv(dir / "out" / motion);
    CHECK(unitEntry(b, "x") == "mm");
    CHECK(unitEntry(b, "v") == "mm/s");
    CHECK(unitEntry(b, "inertia_force") == "kN");
    CHECK(unitEntry(a, "beta_dot") == "rad/s");  // an angular velocity, not a frequency
    for (std::size_t row = 1; row < a.rows.size(); row += 7) {
      CHECK(cellAt(b, row, "x") == doctest::Approx(cellAt(a, row, "x") * 1000).epsilon(1e-14));
      CHECK(cellAt(b, row, "inertia_force") ==
            doctest::Approx(cellAt(a, row, "inertia_force") / 1000).epsilon(1e-14));
    }
    // x runs from the outer dead centre: at phi = 180 deg the slider has moved the stroke 2 r.
    bool inner = false;
    for (std::size_t row = 1; row < b.rows.size(); ++row)
      if (cellAt(b, row, "phi") == 180) {
        inner = true;
        CHECK(cellAt(b, row, "x") == doctest::Approx(2 * 18.8).epsilon(1e-12));
      }
    CHECK(inner);
    const std::string gp = readText(dir / "out" / "drive_kinematics.gp");
    CHECK(gp.find("slider position x [mm]") != std::string::npos);
    CHECK(gp.find("slider velocity v [mm/s]") != std::string::npos);
    fs::remove_all(dir);
  }

  TEST_CASE("torsion train: summary, tables and charts in the units") {
    const fs::path dir = scratchDir("units-torsion");
    const std::string units = "force=kN,speed=rad/s,frequency=rpm,angle=deg";
    const ProcessResult si = runBeamrotor(
        {"solve", "problems/snt32_torsion.yaml", "--out", (dir / "si").string()});
    const ProcessResult p = runBeamrotor(
        {"solve", "problems/snt32_torsion.yaml", "--units", units, "--out",
         (dir / "out").string()});
    REQUIRE_MESSAGE(si.exitCode == 0, si.err);
    REQUIRE_MESSAGE(p.exitCode == 0, p.err);
    // The deck's motor_speed of 1470 rpm is 1470 pi / 30 rad/s.
    CHECK(p.out.find("steady response at " + six(1470 * std::numbers::pi / 30) + " rad/s") !=
          std::string::npos);
    CHECK(si.out.find("steady response at 1470 rpm") != std::string::npos);
    const nlohmann::json doc = readJson(dir / "out" / "results.json");
    nlohmann::json train;
    for (const nlohmann::json& a : doc["analyses"])
      if (a.contains("train")) train = a["train"];
    REQUIRE_FALSE(train.is_null());
    const double crankshaft = train["response"]["torques_n_m"]["crankshaft"]["peak"].get<double>();
    CHECK(lineWith(p.out, "torque crankshaft:").find(six(crankshaft / 1000) + " kN m") !=
          std::string::npos);
    const double twist = train["response"]["twists_rad"]["motor.start"]["peak"].get<double>();
    CHECK(lineWith(p.out, "twist motor.start:").find(six(twist * 180 / std::numbers::pi) +
                                                      " deg") != std::string::npos);
    const nlohmann::json& crossing = train["interference"]["crossings"][0];
    CHECK(lineWith(p.out, "order " + six(crossing["order"].get<double>()) + " x mode")
              .find(six(crossing["frequency_hz"].get<double>() * 60) + " rpm") !=
          std::string::npos);

    // The torques table: each row names its unit; the SI table's numbers / 1000.
    const std::vector<std::vector<std::string>> a = csvCells(dir / "si" / "drive_torques.csv");
    const std::vector<std::vector<std::string>> b = csvCells(dir / "out" / "drive_torques.csv");
    const std::size_t quantity = csvColumn(b[0], "quantity"), peak = csvColumn(b[0], "peak");
    bool torqueRow = false;
    for (std::size_t row = 1; row < b.size(); ++row) {
      if (b[row][0].rfind("#", 0) == 0) continue;
      if (b[row][quantity] != "torque kN m") continue;
      torqueRow = true;
      CHECK(a[row][quantity] == "torque N m");
      CHECK(std::stod(b[row][peak]) == doctest::Approx(std::stod(a[row][peak]) / 1000).epsilon(1e-14));
    }
    CHECK(torqueRow);
    // The response against speed: speeds in rad/s (rpm x pi/30), torques in kN m.
    const WrittenCsv rs = writtenCsv(dir / "si" / "drive_response.csv");
    const WrittenCsv rb = writtenCsv(dir / "out" / "drive_response.csv");
    CHECK(unitEntry(rb, "speed_rpm") == "rad/s");
    CHECK(unitEntry(rb, "crankshaft") == "kN m");
    const std::size_t last = rb.rows.size() - 1;
    CHECK(cellAt(rb, last, "speed_rpm") ==
          doctest::Approx(cellAt(rs, last, "speed_rpm") * std::numbers::pi / 30).epsilon(1e-14));
    CHECK(cellAt(rb, last, "speed_rpm") == doctest::Approx(1800 * std::numbers::pi / 30).epsilon(1e-12));
    CHECK(cellAt(rb, last, "crankshaft") ==
          doctest::Approx(cellAt(rs, last, "crankshaft") / 1000).epsilon(1e-14));
    const WrittenCsv ib = writtenCsv(dir / "out" / "drive_interference.csv");
    CHECK(unitEntry(ib, "mode_2") == "rpm");
    const std::string interference = readText(dir / "out" / "drive_interference.gp");
    CHECK(interference.find("speed of motor [rad/s]") != std::string::npos);
    CHECK(interference.find("frequency [rpm]") != std::string::npos);
    CHECK(readText(dir / "out" / "drive_response.gp").find("peak [kN m]") != std::string::npos);
    fs::remove_all(dir);
  }
}

TEST_SUITE("output units (every place)") {
  TEST_CASE("API 684 Level I: the table, the chart's axis and marked Qa and Q0 in the units") {
    const fs::path dir = scratchDir("units-level1");
    const ProcessResult p = runBeamrotor(
        {"solve", "problems/level1_stability.yaml", "--units", "force=kN,length=mm,speed=Hz",
         "--out", (dir / "out").string()});
    REQUIRE_MESSAGE(p.exitCode == 0, p.err);
    const nlohmann::json doc = readJson(dir / "out" / "results.json");
    const nlohmann::json& a = doc["analyses"][0];
    const double qa = a["qa"].get<double>(), q0 = a["q0"].get<double>();
    // kN/mm = 1e6 N/m; the chart's marks are the SI figures / 1e6.
    const WrittenCsv table = writtenCsv(dir / "out" / "level1_level1.csv");
    CHECK(unitEntry(table, "cross_coupling") == "kN/mm");
    const std::string gp = readText(dir / "out" / "level1_level1.gp");
    CHECK(gp.find("added cross-coupling Q [kN/mm]") != std::string::npos);
    CHECK(gp.find("using ($1*1):2") != std::string::npos);  // the table holds kN/mm already
    CHECK(gp.find("Qa = " + labelNumber(qa * 1e-6) + " kN/mm") != std::string::npos);
    CHECK(gp.find("Q0 = " + labelNumber(q0 * 1e-6) + " kN/mm") != std::string::npos);
    // The caption's speed: 3000 rpm = 50 turns per second.
    CHECK(gp.find("at 50 Hz, cross-coupling") != std::string::npos);
    // The check table: Qa with its unit, API 617's figure / 1e6.
    CHECK(lineWith(p.out, "level1 qa").find("ref " + six(qa * 1e-6) + " kN/mm") !=
          std::string::npos);
    fs::remove_all(dir);
  }
}

TEST_SUITE("output units (every place)") {
  TEST_CASE("a transient sweep's table: the swept values and the history maxima in the units") {
    const fs::path dir = scratchDir("units-transient");
    const ProcessResult si = runBeamrotor({"solve", "problems/mo10_steady.yaml", "--charts",
                                           "none", "--out", (dir / "si").string()});
    const ProcessResult kn =
        runBeamrotor({"solve", "problems/mo10_steady.yaml", "--charts", "none", "--units",
                      "force=kN", "--out", (dir / "kn").string()});
    REQUIRE_MESSAGE(si.exitCode == 0, si.err);
    REQUIRE_MESSAGE(kn.exitCode == 0, kn.err);
    CHECK(kn.out.find("c kN/m") != std::string::npos);
    CHECK(kn.out.find("spring_force_max kN") != std::string::npos);
    CHECK(si.out.find("c N/m") != std::string::npos);
    // The first value, c = 10 kN/m: its row in kN/m and kN is the SI row's numbers / 1000.
    const auto cells = [](const std::string& line) {
      std::vector<double> out;
      std::istringstream s(line);
      for (double v; s >> v;) out.push_back(v);
      return out;
    };
    const std::vector<double> a = cells(lineWith(si.out, "  10000  ")),
                              b = cells(lineWith(kn.out, "  10  "));
    REQUIRE(a.size() == 4);
    REQUIRE(b.size() == 4);
    CHECK(b[0] == 10);
    CHECK(b[1] == a[1]);  // phi_max in rad either way
    CHECK(b[2] == doctest::Approx(a[2] / 1000).epsilon(1e-5));  // six printed digits
    fs::remove_all(dir);
  }
}

TEST_SUITE("output units (design studies, tables with a unit per row)") {
  TEST_CASE("a design study: its summary in the units, study.csv in the units it names") {
    const fs::path dir = scratchDir("units-study");
    const auto study = [&](const std::string& out, const std::vector<std::string>& more) {
      std::vector<std::string> arguments{
          "study",    "problems/pump_rod.yaml", "--sweep", "eta=0:0.4:4", "--sweep",
          "w0=0.5e-3:1.5e-3:2", "--output", "stress max <= 60 MPa", "--output",
          "reaction left uy", "--out", (dir / out).string()};
      arguments.insert(arguments.end(), more.begin(), more.end());
      return runBeamrotor(arguments);
    };
    const ProcessResult si = study("si", {});
    const ProcessResult mm = study("mm", {"--units", "length=mm,force=kN,stress=MPa"});
    REQUIRE_MESSAGE(si.exitCode == 0, si.err);
    REQUIRE_MESSAGE(mm.exitCode == 0, mm.err);
    // study.csv: the same bytes whatever the units (a resumed study continues it), each
    // column's unit named on its units line.
    CHECK(fileContents(dir / "mm" / "study.csv") == fileContents(dir / "si" / "study.csv"));
    const WrittenCsv table = writtenCsv(dir / "mm" / "study.csv");
    CHECK(unitEntry(table, "eta") == "m");
    CHECK(unitEntry(table, "w0") == "m");
    CHECK(unitEntry(table, "stress max") == "Pa");
    CHECK(unitEntry(table, "reaction left uy") == "N");
    CHECK(unitEntry(table, "M1 published") == "N m");
    CHECK(unitEntry(table, "M1 published pass") == "");
    CHECK(unitEntry(table, "middle rotation closed form") == "rad");
    CHECK(unitEntry(table, "status") == "");
    // summary.json: the same document, its numbers in the columns' units, which it names.
    const nlohmann::json summary = readJson(dir / "mm" / "summary.json");
    CHECK(summary == readJson(dir / "si" / "summary.json"));
    CHECK(summary["parameters"][0]["unit"] == "m");
    const nlohmann::json& stress = summary["outputs"][0];
    const nlohmann::json& force = summary["outputs"][1];
    CHECK(stress["unit"] == "Pa");
    CHECK(force["unit"] == "N");
    CHECK(summary["checks"][0]["unit"] == "N m");
    // The printed summary: the SI figures times the units' factors, each unit named.
    const std::string stressLine = lineWith(mm.out, "  stress max");
    CAPTURE(stressLine);
    CHECK(stressLine.find("min " + six(stress["min"].get<double>() * 1e-6) + " MPa") !=
          std::string::npos);
    CHECK(stressLine.find("sd " + six(stress["sd"].get<double>() * 1e-6) + " MPa") !=
          std::string::npos);
    CHECK(stressLine.find("above 60 MPa") != std::string::npos);
    CHECK(lineWith(si.out, "  stress max").find("above 6e+07 Pa") != std::string::npos);
    const std::string forceLine = lineWith(mm.out, "  reaction left uy:");
    CAPTURE(forceLine);
    CHECK(forceLine.find("max " + six(force["max"].get<double>() / 1000) + " kN") !=
          std::string::npos);
    const nlohmann::json& worst = summary["worst_point"]["parameters"];
    const double eta = worst["eta"].get<double>(), w0 = worst["w0"].get<double>();
    CHECK(lineWith(mm.out, "worst point").find("eta = " + six(eta * 1000) + " mm, w0 = " +
                                               six(w0 * 1000) + " mm") != std::string::npos);
    CHECK(lineWith(si.out, "worst point").find("eta = " + six(eta) + " m, w0 = " + six(w0) +
                                               " m") != std::string::npos);
    // The worst point's results directory in the units.
    const WrittenCsv fields = writtenCsv(dir / "mm" / "worst" / "bending_fields.csv");
    CHECK(unitEntry(fields, "x") == "mm");
    CHECK(unitEntry(fields, "Vy") == "kN");
    fs::remove_all(dir);
  }

  TEST_CASE("response spectrum: the reactions table's rows in the force and moment units") {
    const fs::path dir = scratchDir("units-spectrum");
    const ProcessResult si = runBeamrotor({"solve", "problems/machine_base_frame.yaml",
                                           "--charts", "none", "--out", (dir / "si").string()});
    const ProcessResult kn =
        runBeamrotor({"solve", "problems/machine_base_frame.yaml", "--charts", "none",
                      "--units", "force=kN", "--out", (dir / "kn").string()});
    REQUIRE_MESSAGE(si.exitCode == 0, si.err);
    REQUIRE_MESSAGE(kn.exitCode == 0, kn.err);
    const auto a = csvCells(dir / "si" / "quake_spectrum_reactions.csv");
    const auto b = csvCells(dir / "kn" / "quake_spectrum_reactions.csv");
    REQUIRE(a.size() == b.size());
    REQUIRE(a.size() > 2);
    const std::size_t unit = csvColumn(b[0], "unit"), combined = csvColumn(b[0], "combined");
    int forces = 0, moments = 0;
    for (std::size_t row = 1; row < b.size(); ++row) {
      CAPTURE(row);
      const bool moment = a[row][unit] == "N m";
      CHECK(a[row][unit] == (moment ? "N m" : "N"));
      CHECK(b[row][unit] == (moment ? "kN m" : "kN"));
      (moment ? moments : forces)++;
      // Every value column: the SI value / 1000 (to the round-off of one division).
      for (std::size_t column = combined; column < b[row].size(); ++column)
        CHECK(std::stod(b[row][column]) ==
              doctest::Approx(std::stod(a[row][column]) / 1000).epsilon(1e-15));
    }
    CHECK(forces > 0);
    CHECK(moments > 0);
    // The summary: results.json's SI peaks / 1000, in kN and kN m.
    const nlohmann::json doc = readJson(dir / "kn" / "results.json");
    const nlohmann::json& peaks = doc["analyses"][0]["combined"];
    CHECK(lineWith(kn.out, "combined peaks").find(
              "x " + six(peaks["base_force_n"]["x"].get<double>() / 1000) + " kN") !=
          std::string::npos);
    const double a0 = peaks["reactions"][0]["value"].get<double>();
    CHECK(lineWith(kn.out, "reaction A0 ux").find(six(a0 / 1000) + " kN") != std::string::npos);
    CHECK(lineWith(kn.out, "reaction A0 rx").find(" kN m") != std::string::npos);
    CHECK(lineWith(si.out, "reaction A0 ux").find(six(a0) + " N") != std::string::npos);
    CHECK(lineWith(kn.out, "base force max").find(" kN") != std::string::npos);
    fs::remove_all(dir);
  }

  TEST_CASE("moving load: the envelopes table's rows in their quantities' units") {
    const fs::path dir = scratchDir("units-moving");
    const ProcessResult si = runBeamrotor({"solve", "problems/crane_girder.yaml", "--charts",
                                           "none", "--out", (dir / "si").string()});
    const ProcessResult mm =
        runBeamrotor({"solve", "problems/crane_girder.yaml", "--charts", "svg", "--units",
                      "force=kN,length=mm", "--out", (dir / "mm").string()});
    REQUIRE_MESSAGE(si.exitCode == 0, si.err);
    REQUIRE_MESSAGE(mm.exitCode == 0, mm.err);
    fs::path file;
    for (const auto& entry : fs::directory_iterator(dir / "mm"))
      if (entry.path().filename().string().ends_with("_envelopes.csv")) file = entry.path();
    REQUIRE_FALSE(file.empty());
    const auto a = csvCells(dir / "si" / file.filename());
    const auto b = csvCells(file);
    REQUIRE(a.size() == b.size());
    const std::size_t unit = csvColumn(b[0], "unit");
    // N -> kN: / 1000; N m -> kN mm: x 1; m -> mm: x 1000; rad stays.
    const std::map<std::string, std::pair<std::string, double>> expected{
        {"N", {"kN", 1e-3}}, {"N m", {"kN mm", 1}}, {"m", {"mm", 1e3}}, {"rad", {"rad", 1}}};
    for (std::size_t row = 1; row < b.size(); ++row) {
      CAPTURE(row);
      const auto& [shown, factor] = expected.at(a[row][unit]);
      CHECK(b[row][unit] == shown);
      for (const char* column : {"max", "min"}) {
        const std::size_t k = csvColumn(b[0], column);
        CHECK(std::stod(b[row][k]) ==
              doctest::Approx(std::stod(a[row][k]) * factor).epsilon(1e-15));
      }
      // The first wheel's place is a length column: mm on the units line.
      const std::size_t lead = csvColumn(b[0], "first_wheel_at_max");
      CHECK(std::stod(b[row][lead]) == doctest::Approx(std::stod(a[row][lead]) * 1000).epsilon(1e-15));
    }
    // The summary and the chart: results.json's SI envelope times the factors. The textbook
    // figures: the largest left reaction 101.25 kN with the first wheel at 2.5 m.
    const nlohmann::json doc = readJson(dir / "mm" / "results.json");
    const nlohmann::json& reaction = doc["analyses"][0]["quantities"][1];
    REQUIRE(reaction["quantity"] == "reaction left uy");
    const double most = reaction["max"]["value"].get<double>();
    const double at = reaction["max"]["first_wheel_at"].get<double>();
    CHECK(most == doctest::Approx(101250).epsilon(1e-12));
    const std::string line = lineWith(mm.out, "reaction left uy: max");
    CAPTURE(line);
    CHECK(line.find("max " + six(most / 1000) + " kN (first wheel at " + six(at * 1000) +
                    " mm)") != std::string::npos);
    CHECK(lineWith(mm.out, "wheel(s) along").find(" 8000 mm of path") != std::string::npos);
    CHECK(lineWith(si.out, "reaction left uy: max").find("max 101250 N (first wheel at 2.5 m)") !=
          std::string::npos);
    const std::string chart = readText(dir / "mm" / "trolley_influence.gp");
    CHECK(chart.find("unit load at s along the path [mm]") != std::string::npos);
    CHECK(chart.find("reaction left uy [-]") != std::string::npos);  // N per N
    CHECK(chart.find("displacement mid uy [mm/kN]") != std::string::npos);
    CHECK(chart.find("max " + labelNumber(most / 1000) + " kN (first wheel at 2500 mm)") !=
          std::string::npos);
    CHECK(chart.find("set xrange [0:8000]") != std::string::npos);
    fs::remove_all(dir);
  }
}

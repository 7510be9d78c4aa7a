// The writers' building blocks: displacements between nodes in any element frame, distance
// along the line, mode-shape scaling, file stems, CSV quoting and the JSON non-finite guard.
#include <doctest/doctest.h>

#include <cmath>
#include <limits>
#include <sstream>
#include <variant>

#include "elements/Spring.hpp"
#include "problems/output/files/CsvTable.hpp"
#include "problems/output/files/FileNames.hpp"
#include "problems/output/JsonWriter.hpp"
#include "problems/output/structure/LineSampling.hpp"
#include "problems/output/structure/ModeShapes.hpp"
#include "tests/problems/output/OutputFixtures.hpp"

using namespace beamrotor;
using namespace beamrotor::test;

namespace {

// Hermite interpolation of an exact EB solution: round-off only.
constexpr double kPartsExact = 1e-10;

}  // namespace

TEST_SUITE("output") {
  TEST_CASE("displacementAt: bending about local y (uz, ry) in a 3D frame is exact") {
    // Tip force +P along z: w(x) = P x^2 (3L - x) / (6 EI), ry = -dw/dx (right-hand rule).
    const double L = 1.5, P = 900;
    const auto section = steelRectangle(0.04, 0.06);
    Model model;
    const Line line = uniformBeam(model, L, section, 3, DofSet::frame3d());
    clamp(model, "root", line.nodes.front(), DofSet::frame3d());
    model.addLoad({line.nodes.back(), Dof::uz, P});
    const StaticResult r = solveStatic(model);
    const double EI = section->EIy();
    const double tip = P * L * L * L / (3 * EI);
    for (const StaticStation& st : sampleStatics({model, r.displacement})) {
      const double x = st.place.x;
      CAPTURE(x);
      CHECK(std::abs(st.displacement[2] - P * x * x * (3 * L - x) / (6 * EI)) <= kPartsExact * tip);
      CHECK(std::abs(st.displacement[4] + P * x * (2 * L - x) / (2 * EI)) <= kPartsExact * tip / L);
      CHECK(std::abs(st.displacement[1]) <= kPartsExact * tip);
    }
  }

  TEST_CASE("displacementAt: a line at 45 degrees deflects like the same line along x") {
    // Planar cantilever along (1, 1)/sqrt(2) with a tip force P perpendicular to it: the
    // deflection along the normal n = (-1, 1)/sqrt(2) is P s^2 (3L - s) / (6 EI).
    const double L = 2.0, P = 1200;
    const auto section = steelCircle(0.05);
    const Eigen::Vector3d axis(1 / std::sqrt(2.0), 1 / std::sqrt(2.0), 0);
    const Eigen::Vector3d normal(-axis.y(), axis.x(), 0);
    Model model;
    LineSpec spec;
    spec.direction = axis;
    spec.segments.push_back({L, section, 4, 0, {}});
    const Line line = buildLine(model, spec);
    clamp(model, "root", line.nodes.front(), DofSet::planar());
    model.addLoad({line.nodes.back(), Dof::ux, P * normal.x()});
    model.addLoad({line.nodes.back(), Dof::uy, P * normal.y()});
    const StaticResult r = solveStatic(model);
    const double EI = section->EIz(), tip = P * L * L * L / (3 * EI);
    for (const StaticStation& st : sampleStatics({model, r.displacement})) {
      const double s = st.place.x;
      CAPTURE(s);
      const Eigen::Vector3d u(st.displacement[0], st.displacement[1], st.displacement[2]);
      CHECK(std::abs(u.dot(normal) - P * s * s * (3 * L - s) / (6 * EI)) <= kPartsExact * tip);
      CHECK(std::abs(st.displacement[5] - P * s * (2 * L - s) / (2 * EI)) <= kPartsExact * tip / L);
    }
  }

  TEST_CASE("lineCoordinates: distance along the line; nodes off the line have none") {
    Model model;
    const Line line = uniformBeam(model, 3.0, steelCircle(0.05), 3);
    const int loose = model.addNode({5, 5, 0});
    model.add<Spring>(NodeDof{loose, Dof::uy}, 1e6);
    const auto x = lineCoordinates(model);
    for (int k = 0; k < 4; ++k) CHECK(x[line.nodes[k]] == doctest::Approx(k).epsilon(1e-15));
    CHECK_FALSE(x[loose].has_value());
  }

  TEST_CASE("displayModeShape: largest translation 1 and positive; torsion by rotation") {
    Model model;
    uniformBeam(model, 1.0, steelCircle(0.05), 2);
    NodalField shape = NodalField::Zero(3, kDofKinds);
    shape(1, 1) = -4e-3;
    shape(2, 1) = 2e-3;
    shape(2, 5) = 1e-2;
    const NodalField scaled = displayModeShape(model, shape);
    CHECK(scaled(1, 1) == 1.0);
    CHECK(scaled(2, 1) == -0.5);
    CHECK(scaled(2, 5) == doctest::Approx(-2.5).epsilon(1e-15));
    CHECK(dominantTranslation(scaled) == Dof::uy);

    NodalField torsion = NodalField::Zero(3, kDofKinds);
    torsion(2, 3) = 0.3;
    torsion(2, 1) = 1e-20;  // round-off, not a translation
    const NodalField t = displayModeShape(model, torsion);
    CHECK(t(2, 3) == 1.0);
  }

  TEST_CASE("file stems are safe; colliding names are refused") {
    CHECK(fileStem("eta = 0.4 / left") == "eta___0.4___left");
    CHECK(fileStem("static-1_a.b") == "static-1_a.b");
    CHECK(fileStem("..") == "analysis..");
    std::vector<AnalysisOutcome> two(2);
    two[0].name = "a b";
    two[1].name = "a?b";
    CHECK_THROWS_AS(requireDistinctFileStems(two), std::invalid_argument);
    two[1].name = "a_c";
    CHECK_NOTHROW(requireDistinctFileStems(two));
    CHECK(sweepValueDirectory(7, 12) == "value_007");
    CHECK(sweepValueDirectory(1234, 2000) == "value_1234");
  }

  TEST_CASE("CsvTable: RFC 4180 quoting, exact numbers, refuses NaN naming the cell") {
    CsvTable table("t.csv", {{"mode", ""}, {"description", ""}, {"f", "Hz"}});
    table.addRow({1LL, std::string("bending, \"stiff\""), 0.1});
    CHECK_THROWS_WITH_AS(table.addRow({2LL, std::string("x"), std::nan("")}),
                         doctest::Contains("column 'f', row 2"), std::runtime_error);
    CHECK_THROWS_AS(table.addRow({2LL}), std::invalid_argument);
    CHECK(table.column("f") == 3);
    ScratchDir scratch;
    table.write(scratch / "t.csv");
    CHECK(readText(scratch / "t.csv") ==
          "mode,description,f\n# units: ,,Hz\n1,\"bending, \"\"stiff\"\"\",0.1\n");
    // Text that needs no quotes has none (NumPy's genfromtxt keeps quotes as part of a text);
    // a '#', which NumPy and gnuplot take for a comment, and spaces at an end are quoted.
    CsvTable plain("p.csv", {{"case", ""}, {"value", ""}});
    for (const char* name : {"ULS both", "#2", " edge"}) plain.addRow({std::string(name), 1.0});
    plain.write(scratch / "p.csv");
    CHECK(readText(scratch / "p.csv") == "case,value\nULS both,1\n\"#2\",1\n\" edge\",1\n");
  }

  TEST_CASE("CsvTable: every kind of cell reads back and writes as it was given") {
    // Cells are held as a kind and 8 bytes, texts once each: what goes in must come out, in
    // cell(), numbers() and the file, whatever the order of kinds and repeats of texts.
    CsvTable t("k.csv", {{"member", ""}, {"x", "m"}, {"element", ""}, {"F", "N"}});
    const double tiny = std::numeric_limits<double>::denorm_min();
    t.addRow({std::string("m1"), -0.0, 7LL, CsvCell{std::monostate{}}});
    t.addRow({std::string("m2"), 0.1 + 0.2, -3LL, tiny});
    t.addRow({std::string("m1"), 1e300, 9007199254740993LL, -2.5});
    CHECK(t.rowCount() == 3);
    CHECK(std::get<std::string>(t.cell(2, 0)) == "m1");
    CHECK(std::get<double>(t.cell(1, 1)) == 0.1 + 0.2);  // bit for bit
    CHECK(std::get<long long>(t.cell(2, 2)) == 9007199254740993LL);  // beyond a double's 2^53
    CHECK(std::holds_alternative<std::monostate>(t.cell(0, 3)));
    const std::vector<double> F = t.numbers("F");
    CHECK(std::isnan(F[0]));
    CHECK(F[1] == tiny);
    CHECK(t.numbers("element") == std::vector<double>{7, -3, 9007199254740992.0});
    CHECK_THROWS_AS(t.numbers("member"), std::invalid_argument);
    CHECK_THROWS_AS(t.cell(3, 0), std::out_of_range);
    std::ostringstream out;
    t.writeTo(out);
    CHECK(out.str() == "member,x,element,F\n# units: ,m,,N\nm1,0,7,\nm2,0.30000000000000004,-3,"
                       "5e-324\nm1,1e+300,9007199254740993,-2.5\n");
    // Converted in place: numbers scaled, counts, texts and empty cells kept; a product that
    // leaves the doubles is refused as addRow refuses it.
    t.convertColumn(3, 1e-3, "kN");
    t.convertColumn(2, 1e-3, "");
    CHECK(t.columns()[3].unit == "kN");
    CHECK(std::get<double>(t.cell(2, 3)) == -2.5 * 1e-3);
    CHECK(std::get<long long>(t.cell(0, 2)) == 7);
    CHECK_THROWS_WITH_AS(t.convertColumn(1, 1e10, "x"), doctest::Contains("column 'x', row 3"),
                         std::runtime_error);
  }

  TEST_CASE("requireFiniteNumbers names the JSON path of a NaN") {
    Json doc = {{"analyses", Json::array({{{"max_stress", {{"value", 1.0}}}}})}};
    CHECK_NOTHROW(requireFiniteNumbers(doc, "results.json"));
    doc["analyses"][0]["max_stress"]["value"] = std::numeric_limits<double>::infinity();
    CHECK_THROWS_WITH_AS(requireFiniteNumbers(doc, "results.json"),
                         doctest::Contains("results.json: /analyses/0/max_stress/value"),
                         std::runtime_error);
  }
}

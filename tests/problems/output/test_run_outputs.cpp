// The outputs of one run against the cantilever's closed forms: results.json, the fields
// CSV, the VTK files (read back by VTK and by meshio), the mode collection and the charts.
#include <doctest/doctest.h>
#include <vtkCellData.h>
#include <vtkDataArray.h>
#include <vtkFieldData.h>
#include <vtkNew.h>
#include <vtkPointData.h>
#include <vtkUnstructuredGrid.h>
#include <vtkXMLUnstructuredGridReader.h>

#include <cmath>
#include <cstdio>
#include <numbers>
#include <regex>

#include "problems/output/Output.hpp"
#include "tests/problems/output/OutputFixtures.hpp"

using namespace beamrotor;
using namespace beamrotor::test;
namespace fs = std::filesystem;

namespace {

// Hermite cubics make the EB cantilever exact (see tests/fem/static/test_cantilever.cpp): the solve
// and the recovery leave only round-off, ~1e6 (condition) x 1e-16 (machine epsilon).
constexpr double kRunOutputsExact = 1e-10;

vtkSmartPointer<vtkUnstructuredGrid> readOutputVtu(const fs::path& file) {
  vtkNew<vtkXMLUnstructuredGridReader> reader;
  reader->SetFileName(file.string().c_str());
  reader->Update();
  return reader->GetOutput();
}

/// Runs /usr/bin/python3 with a script; its standard output, or nullopt when it cannot run.
std::optional<std::string> python(const std::string& script, int* status) {
  const std::string command = "/usr/bin/python3 -c '" + script + "' 2>&1";
  FILE* pipe = popen(command.c_str(), "r");
  if (!pipe) return std::nullopt;
  std::string out;
  char buffer[256];
  while (fgets(buffer, sizeof buffer, pipe)) out += buffer;
  *status = pclose(pipe);
  return out;
}

bool meshioInstalled() {
  int status = -1;
  const auto out = python("import meshio", &status);
  return out && status == 0;
}

}  // namespace

TEST_SUITE("output") {
  TEST_CASE("results.json reports the cantilever's closed-form reactions and deflection") {
    const Cantilever c;
    const RunResult run = cantileverRun(c);
    const StaticResult& r = *staticsOf(run.analyses[0]);
    ScratchDir scratch;
    writeRunOutputs(run, scratch / "out");
    const nlohmann::json doc = readJson(scratch / "out" / "results.json");

    SUBCASE("model") {
      CHECK(doc["model"]["nodes"] == c.elements + 1);
      CHECK(doc["model"]["elements"] == c.elements);
      CHECK(doc["model"]["dofs"] == r.size.dofs);  // 3 planar dofs per node
      CHECK(doc["model"]["dofs"] == 3 * (c.elements + 1));
      CHECK(doc["model"]["dimension"] == "planar");
    }
    SUBCASE("static entry") {
      const auto& a = doc["analyses"].at(0);
      CHECK(a["type"] == "static");
      CHECK(a["name"] == "tip");
      const auto& root = a["reactions"]["root"];
      // A planar model carries fx, fy, mz only.
      CHECK(root.size() == 3);
      CHECK(root.contains("fx"));
      CHECK_FALSE(root.contains("fz"));
      CHECK(relError(root["fy"].get<double>(), c.P) < kRunOutputsExact);
      CHECK(relError(root["mz"].get<double>(), c.P * c.L) < kRunOutputsExact);
      CHECK(std::abs(root["fx"].get<double>()) <= kRunOutputsExact * c.P);
      const auto& end = a["displacements"]["end"];
      CHECK(end.size() == 3);
      CHECK(relError(end["uy"].get<double>(), c.deflection(c.L)) < kRunOutputsExact);
      // JSON numbers round-trip exactly (17 significant digits): the file holds the result.
      CHECK(end["uy"].get<double>() == r.displacement(c.elements, dofIndex(Dof::uy)));
      CHECK(a["displacements"]["start"]["uy"].get<double>() == 0.0);
      // Largest stress: the root, M = P L on the outer fibre D/2 of I = pi D^4 / 64.
      const double I = std::numbers::pi * std::pow(c.D, 4) / 64;
      CHECK(relError(a["max_stress"]["value"].get<double>(), c.P * c.L * (c.D / 2) / I) <
            kRunOutputsExact);
      CHECK(a["max_stress"]["x"].get<double>() == 0.0);
      CHECK(a["rcond"].get<double>() == r.rcond);
      CHECK(a["files"]["fields_csv"] == "tip_fields.csv");
      CHECK(fs::exists(scratch / "out" / a["files"]["vtu"].get<std::string>()));
    }
    SUBCASE("checks and parameters") {
      const auto& check = doc["checks"].at(0);
      CHECK(check["name"] == "tip deflection");
      CHECK(check["pass"] == true);
      CHECK(check["rel_error"].get<double>() == run.checks[0].relError());
      CHECK(check["reference"].get<double>() == c.deflection(c.L));
      CHECK(doc["parameters"]["P"].get<double>() == c.P);
      // Deck order kept in the file: P before L (plain nlohmann::json would sort the keys).
      std::ifstream in(scratch / "out" / "results.json");
      const auto ordered = nlohmann::ordered_json::parse(in);
      CHECK(ordered["parameters"].begin().key() == "P");
    }
  }

  TEST_CASE("fields CSV: moment P (L - x), Hermite deflection and slope between the nodes") {
    const Cantilever c;
    ScratchDir scratch;
    writeRunOutputs(cantileverRun(c), scratch / "out");
    const NumericCsv csv = readNumericCsv(scratch / "out" / "tip_fields.csv");

    const std::vector<std::string> expected{"x",  "ux", "uy", "uz", "rx", "ry", "rz",
                                            "N",  "Vy", "Vz", "T",  "My", "Mz", "stress",
                                            "shear", "stress_top", "stress_bottom",
                                            "shear_y", "shear_z", "element"};
    CHECK(csv.header == expected);
    // The units on the comment line after the names, one per column.
    const std::string text = readText(scratch / "out" / "tip_fields.csv");
    const std::size_t second = text.find('\n') + 1;
    CHECK(text.substr(second, text.find('\n', second) - second) ==
          "# units: m,m,m,m,rad,rad,rad,N,N,N,N m,N m,N m,Pa,Pa,Pa,Pa,Pa,Pa,");
    REQUIRE(csv.rows.size() == std::size_t(c.elements * 5));  // 4 intervals: 5 stations each
    const int x = csv.column("x"), uy = csv.column("uy"), rz = csv.column("rz"),
              Mz = csv.column("Mz"), shear = csv.column("shear");
    CHECK(csv.rows.front()[x] == 0.0);
    // Shear force P everywhere; largest shear stress of a solid circle by the elasticity
    // solution (Timoshenko & Goodier, art. 124): (3 + 2 nu) / (2 (1 + nu)) P / A.
    const double nu = c.section->material.nu, area = std::numbers::pi * c.D * c.D / 4;
    const double tau = (3 + 2 * nu) / (2 * (1 + nu)) * c.P / area;
    CHECK(relError(std::abs(csv.rows.front()[Mz]), c.P * c.L) < kRunOutputsExact);
    const double sign = csv.rows.front()[Mz] > 0 ? 1 : -1;
    const double tip = c.deflection(c.L), tipSlope = c.slope(c.L);
    for (const auto& row : csv.rows) {
      CAPTURE(row[x]);
      // Interior stations are interpolated: exact for EB cubics, so round-off only.
      CHECK(std::abs(row[uy] - c.deflection(row[x])) <= kRunOutputsExact * std::abs(tip));
      CHECK(std::abs(row[rz] - c.slope(row[x])) <= kRunOutputsExact * std::abs(tipSlope));
      CHECK(std::abs(row[Mz] - sign * c.P * (c.L - row[x])) <= kRunOutputsExact * c.P * c.L);
      CHECK(relError(row[shear], tau) < kRunOutputsExact);
    }
  }

  TEST_CASE("VTK file read back by VTK and by meshio holds the written mesh and displacement") {
    const Cantilever c;
    const RunResult run = cantileverRun(c);
    const NodalField& u = staticsOf(run.analyses[0])->displacement;
    ScratchDir scratch;
    writeRunOutputs(run, scratch / "out");
    const fs::path file = scratch / "out" / "tip.vtu";

    SUBCASE("VTK reader") {
      const auto grid = readOutputVtu(file);
      REQUIRE(grid);
      CHECK(grid->GetNumberOfPoints() == c.elements + 1);
      CHECK(grid->GetNumberOfCells() == c.elements);
      CHECK(grid->GetCellType(0) == VTK_LINE);
      vtkDataArray* d = grid->GetPointData()->GetArray("displacement");
      REQUIRE(d);
      REQUIRE(d->GetNumberOfComponents() == 3);
      // Float64 written and read back: bit-for-bit.
      CHECK(d->GetComponent(c.elements, 1) == u(c.elements, dofIndex(Dof::uy)));
      CHECK(d->GetComponent(c.elements, 0) == u(c.elements, dofIndex(Dof::ux)));
      vtkDataArray* rotation = grid->GetPointData()->GetArray("rotation");
      REQUIRE(rotation);
      CHECK(rotation->GetComponent(c.elements, 2) == u(c.elements, dofIndex(Dof::rz)));
      // Cell data at mid-length of element 0: |Mz| = P (L - h/2).
      const double h = c.L / c.elements;
      vtkDataArray* Mz = grid->GetCellData()->GetArray("Mz");
      REQUIRE(Mz);
      CHECK(relError(std::abs(Mz->GetTuple1(0)), c.P * (c.L - h / 2)) < kRunOutputsExact);
      vtkDataArray* A = grid->GetCellData()->GetArray("A");
      REQUIRE(A);
      CHECK(A->GetTuple1(2) == c.section->A);
      // Stress: the largest over element 0 is at the root.
      vtkDataArray* stress = grid->GetCellData()->GetArray("stress");
      REQUIRE(stress);
      CHECK(relError(stress->GetTuple1(0), c.P * c.L * c.section->outerY / c.section->Iz) <
            kRunOutputsExact);
      // Shear force P throughout: the elasticity solution's (3 + 2 nu) / (2 (1 + nu)) P / A.
      vtkDataArray* shear = grid->GetCellData()->GetArray("shear");
      REQUIRE(shear);
      const double nu = c.section->material.nu;
      CHECK(relError(shear->GetTuple1(0), (3 + 2 * nu) / (2 * (1 + nu)) * c.P / c.section->A) <
            kRunOutputsExact);
    }
    SUBCASE("meshio") {
      if (!meshioInstalled()) {
        MESSAGE("/usr/bin/python3 has no meshio: meshio read-back skipped");
        return;
      }
      int status = -1;
      const auto out = python(
          "import meshio; m = meshio.read(\"" + file.string() +
              "\"); print(len(m.points), sum(len(b.data) for b in m.cells if b.type == \"line\"), "
              "repr(float(m.point_data[\"displacement\"][-1][1])))",
          &status);
      REQUIRE(out);
      CAPTURE(*out);
      REQUIRE(status == 0);
      std::istringstream words(*out);
      int points = 0, lines = 0;
      double tipDeflection = 0;
      words >> points >> lines >> tipDeflection;
      CHECK(points == c.elements + 1);
      CHECK(lines == c.elements);
      // Python's repr prints the shortest round-tripping decimal: equality is exact.
      CHECK(tipDeflection == u(c.elements, dofIndex(Dof::uy)));
    }
  }

  TEST_CASE("modal outputs: one .vtu per mode listed in the .pvd, table matches the result") {
    const Cantilever c;
    const int modes = 4;
    const RunResult run = cantileverRun(c, modes);
    const ModalResult& modal = *resultOf<ModalResult>(run.analyses[1]);
    ScratchDir scratch;
    writeRunOutputs(run, scratch / "out");
    const fs::path out = scratch / "out";

    const std::string pvd = readText(out / "modes.pvd");
    const std::regex dataset("<DataSet timestep=\"([0-9.]+)\"[^>]* file=\"([^\"]+)\"");
    std::vector<std::string> files;
    for (auto it = std::sregex_iterator(pvd.begin(), pvd.end(), dataset);
         it != std::sregex_iterator(); ++it) {
      CHECK(std::stod((*it)[1]) == double(files.size() + 1));  // mode numbers as time steps
      files.push_back((*it)[2]);
    }
    REQUIRE(files.size() == std::size_t(modes));
    for (const std::string& f : files) CHECK(fs::exists(out / f));

    const auto grid = readOutputVtu(out / files[0]);
    vtkDataArray* shape = grid->GetPointData()->GetArray("mode_shape");
    REQUIRE(shape);
    double largest = 0;
    for (vtkIdType p = 0; p < shape->GetNumberOfTuples(); ++p) {
      const double* t = shape->GetTuple3(p);
      largest = std::max(largest, std::sqrt(t[0] * t[0] + t[1] * t[1] + t[2] * t[2]));
    }
    // Scaled so the largest translation is 1: one division, round-off only.
    CHECK(std::abs(largest - 1) < 1e-14);
    vtkDataArray* frequency = grid->GetFieldData()->GetArray("frequency_hz");
    REQUIRE(frequency);
    CHECK(frequency->GetTuple1(0) == modal.modes[0].frequencyHz);

    const nlohmann::json doc = readJson(out / "results.json");
    const auto& entry = doc["analyses"].at(1);
    CHECK(entry["type"] == "modal");
    REQUIRE(entry["frequencies_hz"].size() == std::size_t(modes));
    for (int m = 0; m < modes; ++m) {
      CHECK(entry["frequencies_hz"][m].get<double>() == modal.modes[m].frequencyHz);
      if (m)
        CHECK(entry["frequencies_hz"][m].get<double>() >
              entry["frequencies_hz"][m - 1].get<double>());
      const auto& mode = entry["modes"][m];
      CHECK(mode["description"] == modal.modes[m].description);
      CHECK(mode["effective_mass_kg"].size() == 2);  // planar: ux and uy carry mass
      CHECK(mode["effective_mass_ratio"]["uy"].get<double>() ==
            modal.modes[m].effectiveMass[1] / modal.totalMass[1]);
    }
    const std::string table = readText(out / "modes_modes.csv");
    // The names, their units, one line per mode.
    CHECK(std::count(table.begin(), table.end(), '\n') == modes + 2);
    CHECK(table.rfind("mode,frequency,description,", 0) == 0);
    CHECK(table.find("\n# units: ,Hz,,") != std::string::npos);
  }

  TEST_CASE("charts: SVG and PNG drawn by gnuplot, with the script kept") {
    const Cantilever c;
    ScratchDir scratch;
    writeRunOutputs(cantileverRun(c, 3), scratch / "out", {ChartFormat::both, false});
    const fs::path out = scratch / "out";
    for (const std::string chart : {"tip_diagrams", "modes_shapes"}) {
      CAPTURE(chart);
      CHECK(fs::exists(out / (chart + ".gp")));
      CHECK_FALSE(fs::exists(out / (chart + ".log")));  // kept only when gnuplot failed
      REQUIRE(fs::exists(out / (chart + ".svg")));
      const std::string svg = readText(out / (chart + ".svg"));
      CHECK(svg.find("<svg") != std::string::npos);
      CHECK(svg.size() > 1000);
      const std::string png = readText(out / (chart + ".png"));
      REQUIRE(png.size() > 8);
      CHECK(png.compare(1, 3, "PNG") == 0);
    }
  }
}

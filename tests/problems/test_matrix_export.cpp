// Matrix Market export (`solve --export-matrices`, `bench --export`): the files read back
// bit for bit as the assembled matrices, and solving the exported system with another solver
// reproduces the deck's displacements.
#include <doctest/doctest.h>

#include <Eigen/SparseLU>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <unsupported/Eigen/SparseExtra>

#include "fem/assembly/Assembly.hpp"
#include "fem/assembly/ReducedSystem.hpp"
#include "problems/bench/Bench.hpp"
#include "problems/output/structure/MatrixExport.hpp"
#include "problems/run/Study.hpp"
#include "tests/problems/DeckTestSupport.hpp"

using namespace beamrotor;
using namespace beamrotor::test;

namespace {

/// Two spans, a settlement prescribed at the middle support (so f = f_F - K_FC u_C is more
/// than the loads), a distributed and a point load, and a spring.
const char* kExportDeck = R"(title: two spans with a settlement
parameters: {L: 1.0}
model: {dimension: planar, formulation: timoshenko, mass: consistent}
materials:
  - {name: steel, E: 210e9, nu: 0.3, rho: 7850}
sections:
  - {name: rod, shape: circle, D: 0.04}
segments:
  - {length: 2*L, section: rod, elements: 12}
points:
  - {name: middle, at: L}
  - {name: quarter, at: L/2}
supports:
  - {name: left, at: start, fix: [ux, uy]}
  - {name: middle, at: middle, prescribe: {uy: -0.002}}
  - {name: right, at: end, fix: [uy]}
springs:
  - {name: soft, at: quarter, dof: rz, k: 1e4}
loads:
  - {type: distributed, qy: -500}
  - {type: point, at: quarter, fy: -2000}
analyses:
  - {type: static}
)";

SparseMatrix readMatrix(const std::filesystem::path& file) {
  SparseMatrix A;
  REQUIRE(Eigen::loadMarket(A, file.string()));
  return A;
}

/// Same size, same stored entries at the same places, same values to the last bit.
bool identical(const SparseMatrix& a, const SparseMatrix& b) {
  if (a.rows() != b.rows() || a.cols() != b.cols() || a.nonZeros() != b.nonZeros()) return false;
  for (int col = 0; col < a.outerSize(); ++col) {
    SparseMatrix::InnerIterator i(a, col), j(b, col);
    for (; i && j; ++i, ++j)
      if (i.row() != j.row() || i.value() != j.value()) return false;
    if (i || j) return false;
  }
  return true;
}

struct DofRow {
  int node = -1;
  Dof dof = Dof::ux;
};

/// dofs.csv: row, node, point, dof, x, y, z (the row is 1-based, in file order).
std::vector<DofRow> readDofs(const std::filesystem::path& file) {
  std::ifstream in(file);
  std::string line;
  std::getline(in, line);  // names
  std::vector<DofRow> rows;
  while (std::getline(in, line)) {
    if (line.rfind("# units:", 0) == 0) continue;
    std::vector<std::string> cells;
    std::stringstream s(line);
    for (std::string cell; std::getline(s, cell, ',');) cells.push_back(cell);
    REQUIRE(cells.size() == 7);
    CHECK(std::stoi(cells[0]) == int(rows.size()) + 1);
    const auto dof = parseDof(cells[3]);  // text needs no quotes
    REQUIRE(dof);
    rows.push_back({std::stoi(cells[1]), *dof});
  }
  return rows;
}

}  // namespace

TEST_SUITE("matrix export") {
  TEST_CASE("a deck's K, M, f read back bit for bit; solving them reproduces its statics") {
    const Study study = solveStudyText(kExportDeck, {"two_spans.yaml", {}, false, "", ""});
    REQUIRE(study.run);
    const Model& model = *study.run->model;
    const auto dir = scratchDir("export_deck");
    const auto files = exportMatrices(model, dir);
    CHECK(files.size() == 4);  // K, M, f, dofs.csv (no gyroscopic terms in a planar beam)
    CHECK(!std::filesystem::exists(dir / kGyroscopicMtx));

    // 1. Bit for bit: Eigen writes max_digits10 (17) significant digits, which read back
    //    exactly (IEEE 754 round trip).
    const DofMap dofs(model);
    const SparseAssembler assembler(model, dofs);
    const SparseMatrix K = readMatrix(dir / kStiffnessMtx);
    CHECK(identical(K, assembler.assemble(MatrixKind::stiffness)));
    CHECK(identical(readMatrix(dir / kMassMtx), assembler.assemble(MatrixKind::mass)));
    Eigen::VectorXd f;
    REQUIRE(Eigen::loadMarketVector(f, (dir / kLoadMtx).string()));
    const Eigen::VectorXd expected =
        reducedRightHandSide(model, dofs, loadVector(model, dofs), prescribedValues(model, dofs));
    REQUIRE(f.size() == expected.size());
    CHECK((f.array() == expected.array()).all());

    // 2. Solving K u = f by another method (Eigen's supernodal-free SparseLU, not CHOLMOD)
    //    gives the deck's displacements at every free dof, as named by dofs.csv. Both are
    //    backward stable: the difference is round-off times cond(K) (~1e7 here), so 1e-8
    //    of the largest displacement is a wide margin that still catches any wrong entry.
    Eigen::SparseLU<SparseMatrix> lu(K);
    REQUIRE(lu.info() == Eigen::Success);
    const Eigen::VectorXd u = lu.solve(f);
    const std::vector<DofRow> rows = readDofs(dir / kDofsCsv);
    REQUIRE(int(rows.size()) == K.rows());
    const StaticResult& statics = *staticsOf(study.run->analyses.at(0));
    const double scale = statics.displacement.cwiseAbs().maxCoeff();
    CHECK(scale > 1e-3);  // the settlement alone moves the beam 2 mm
    double worst = 0;
    for (std::size_t r = 0; r < rows.size(); ++r)
      worst = std::max(worst,
                       std::abs(u[r] - statics.displacement(rows[r].node, dofIndex(rows[r].dof))));
    CHECK(worst < 1e-8 * scale);
  }

  TEST_CASE("beamrotor solve --export-matrices [DIR]") {
    const auto dir = scratchDir("export_cli");
    const auto deck = dir / "two_spans.yaml";
    std::ofstream(deck) << kExportDeck;
    const ProcessResult byDefault = runBeamrotor(
        {"solve", deck.string(), "--out", (dir / "out").string(), "--export-matrices"});
    CHECK(byDefault.exitCode == 0);
    CHECK(byDefault.out.find("matrices: " + (dir / "out" / "matrices").string()) !=
          std::string::npos);
    for (const char* name : {kStiffnessMtx, kMassMtx, kLoadMtx, kDofsCsv})
      CHECK(std::filesystem::exists(dir / "out" / "matrices" / name));
    const ProcessResult chosen =
        runBeamrotor({"solve", deck.string(), "--out", (dir / "out2").string(),
                      "--export-matrices=" + (dir / "mtx").string()});
    CHECK(chosen.exitCode == 0);
    CHECK(std::filesystem::exists(dir / "mtx" / kStiffnessMtx));
    // A sweep exports each run's model (L = 1 and 1.5: 2 runs).
    const ProcessResult swept =
        runBeamrotor({"solve", deck.string(), "--out", (dir / "out3").string(), "--sweep",
                      "L=1:1.5:1", "--export-matrices=" + (dir / "swept").string()});
    CHECK(swept.exitCode == 0);
    CHECK(std::filesystem::exists(dir / "swept" / "run-1" / kStiffnessMtx));
    CHECK(std::filesystem::exists(dir / "swept" / "run-2" / kLoadMtx));
    CHECK(!std::filesystem::exists(dir / "swept" / "run-3"));
  }

  TEST_CASE("bench --export writes the standard model's matrices (rotor: with G)") {
    BenchOptions o;
    o.kind = "rotor";
    o.elements = 8;
    o.modes = 0;
    o.repeat = 1;
    o.exportDir = scratchDir("export_bench").string();
    const BenchReport r = runBench(o);
    CHECK(r.exported.size() == 5);
    const SparseMatrix G = readMatrix(std::filesystem::path(o.exportDir) / kGyroscopicMtx);
    CHECK(G.rows() == r.freeDofs);
    // Per unit speed the gyroscopic matrix is skew-symmetric (Lalanne and Ferraris 1998).
    CHECK(SparseMatrix(G + SparseMatrix(G.transpose())).norm() == 0);
    CHECK(G.norm() > 0);
  }
}

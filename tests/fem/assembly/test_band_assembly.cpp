// Assembly into a band: chosen for a line numbered node by node and for nothing wider, and the
// same entries as the sparse assembler's, to the last bit, on one part or several.
#include <doctest/doctest.h>

#include <memory>

#include "elements/Spring.hpp"
#include "fem/assembly/Assembly.hpp"
#include "fem/assembly/BandAssembly.hpp"
#include "fem/model/DofMap.hpp"
#include "fem/model/Model.hpp"
#include "problems/bench/StandardModels.hpp"
#include "tests/ThreadsSetting.hpp"

using namespace beamrotor;
using beamrotor::test::ThreadsSetting;

namespace {

/// Every entry of the band against the sparse matrix's upper triangle (the one LDL' reads),
/// exactly, and no entry of the sparse matrix outside the band.
void checkEqual(const SymmetricBand& band, const SparseMatrix& sparse) {
  REQUIRE(band.size() == sparse.rows());
  long long outside = 0, differ = 0;
  for (int col = 0; col < sparse.outerSize(); ++col)
    for (SparseMatrix::InnerIterator it(sparse, col); it; ++it) {
      const int row = int(it.row());
      if (row > col) continue;
      if (col - row > band.halfBandwidth())
        outside += it.value() != 0.0;
      else
        differ += band.lower(col, row) != it.value();
    }
  CHECK(outside == 0);
  CHECK(differ == 0);
  SparseMatrix dropped = sparse;
  dropExactZeros(dropped);
  CHECK(band.nonZeros() == dropped.nonZeros());
  CHECK(band.toSparse().nonZeros() == dropped.nonZeros());
}

}  // namespace

TEST_SUITE("band assembly") {
  TEST_CASE("a planar line: half-bandwidth 5, K and M equal the sparse assembler's") {
    const PlanarBenchModel bench = planarBenchModel(200);
    const Model& m = *bench.model;
    const DofMap dofs(m);
    const std::optional<int> kd = stiffnessBand(m, dofs);
    REQUIRE(kd.has_value());
    // A node's ux, uy, rz are three consecutive equations: an element spans 6 of them
    // (fewer at a support), so its first and last are 5 apart.
    CHECK(*kd == 5);
    const auto [K, M] = SparseAssembler(m, dofs).assemble(MatrixKind::stiffness, MatrixKind::mass);
    checkEqual(assembleBand(m, dofs, MatrixKind::stiffness, *kd), K);
    checkEqual(assembleBand(m, dofs, MatrixKind::mass, *kd), M);
    // The band's product is the sparse one's (the same entries, summed in another order).
    const Eigen::VectorXd x = Eigen::VectorXd::LinSpaced(K.rows(), -1.0, 3.0);
    const Eigen::VectorXd y = assembleBand(m, dofs, MatrixKind::stiffness, *kd) * x;
    CHECK((y - K * x).norm() <= 1e-14 * (K.cwiseAbs() * x.cwiseAbs()).norm());
  }

  TEST_CASE("compressed in place: the band's entries without its zeros, in its own storage") {
    const PlanarBenchModel bench = planarBenchModel(30);
    const Model& m = *bench.model;
    const DofMap dofs(m);
    const int kd = stiffnessBand(m, dofs).value();
    SymmetricBand band = assembleBand(m, dofs, MatrixKind::stiffness, kd);
    const SymmetricBand kept = band;
    const CompressedLower L = std::move(band).lowerWithoutZeros();
    CHECK(band.size() == 0);
    // Every entry of the lower band that is not an exact zero off the diagonal, in column
    // order, and nothing else; the storage shortened to just those.
    long long expected = 0, differ = 0;
    const Eigen::Map<const SparseMatrix> view = L.view();
    const Eigen::MatrixXd dense(view);
    for (int j = 0; j < kept.size(); ++j)
      for (int i = 0; i < kept.size(); ++i) {
        const bool inBand = i >= j && i <= j + kd;
        const bool keptEntry = inBand && (i == j || kept.lower(i, j) != 0.0);
        expected += keptEntry;
        differ += dense(i, j) != (inBand ? kept.lower(i, j) : 0.0);
      }
    CHECK(differ == 0);
    CHECK(L.nonZeros() == expected);
    CHECK(L.values.size() == expected);
    CHECK(L.rows.size() == std::size_t(expected));
    // A planar line: a node's axial dof couples with none of its bending ones, so the kept
    // entries are far fewer than the band's n (kd + 1).
    CHECK(expected < (long long)kept.size() * (kd + 1) * 2 / 3);
  }

  TEST_CASE("a spring between far nodes makes the band too wide: the sparse path serves") {
    PlanarBenchModel bench = planarBenchModel(200);
    Model& m = *bench.model;
    m.addElement(std::make_unique<Spring>(NodeDof{3, Dof::uy}, NodeDof{195, Dof::uy}, 2e5));
    const DofMap dofs(m);
    REQUIRE(dofs.isFree(dofs.equation({195, Dof::uy})));  // not a span end: those are pinned
    // Hundreds of equations apart: a band that wide per equation against about 8 entries an
    // equation in the elements.
    CHECK_FALSE(stiffnessBand(m, dofs).has_value());
  }

  TEST_CASE("one part or three: the same bits") {
    const PlanarBenchModel bench = planarBenchModel(150000);
    const DofMap dofs(*bench.model);
    const int kd = stiffnessBand(*bench.model, dofs).value();
    SymmetricBand one, three;
    {
      const ThreadsSetting threads("1");
      one = assembleBand(*bench.model, dofs, MatrixKind::stiffness, kd);
    }
    {
      const ThreadsSetting threads("3");
      three = assembleBand(*bench.model, dofs, MatrixKind::stiffness, kd);
    }
    const std::size_t entries = std::size_t(one.size()) * std::size_t(one.leading());
    CHECK(std::equal(one.data(), one.data() + entries, three.data()));
    // Compressed in place: three parts pack their stretches apart and move them into place.
    CompressedLower packedOne, packedThree;
    {
      const ThreadsSetting threads("1");
      packedOne = std::move(one).lowerWithoutZeros();
    }
    {
      const ThreadsSetting threads("3");
      packedThree = std::move(three).lowerWithoutZeros();
    }
    CHECK(packedOne.columnStarts == packedThree.columnStarts);
    CHECK(packedOne.rows == packedThree.rows);
    CHECK(packedOne.values == packedThree.values);
    CHECK(packedThree.values.size() == packedThree.nonZeros());
  }
}

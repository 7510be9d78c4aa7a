// Passes over the elements split into parts (threads): the same numbers to the last bit on
// one part or several, and the assembled matrices equal to the element matrices summed dof
// by dof.
#include <doctest/doctest.h>

#include <Eigen/Dense>
#include <algorithm>
#include <memory>
#include <stdexcept>
#include <string>
#include <vector>

#include "elements/Beam.hpp"
#include "elements/Spring.hpp"
#include "fem/assembly/Assembly.hpp"
#include "fem/assembly/ParallelParts.hpp"
#include "fem/assembly/Recovery.hpp"
#include "fem/model/DofMap.hpp"
#include "fem/model/Model.hpp"
#include "problems/bench/StandardModels.hpp"
#include "tests/ThreadsSetting.hpp"

using namespace beamrotor;
using beamrotor::test::ThreadsSetting;

namespace {

/// The planar bench line of `elements` elements with what a line's passes must get right
/// besides: a hinge (a released end rotation), a spring between two nodes far apart (an
/// element whose columns fall in different parts), a node with no free dof left (its support
/// also holds the rotation) and a nodal load on a supported dof (which the reaction nets out).
std::unique_ptr<Model> awkwardLine(int elements) {
  PlanarBenchModel bench = planarBenchModel(elements);
  Model& m = *bench.model;
  static_cast<Beam&>(*m.elements()[5]).release(1, Dof::rz);
  const int last = elements;
  m.addElement(std::make_unique<Spring>(NodeDof{3, Dof::uy}, NodeDof{last - 3, Dof::uy}, 2e5));
  const int clamped = (elements / 20) * 10;  // a span end: ux and uy are pinned already
  m.addSupport({"clamp", clamped, {{Dof::rz, 0}}});
  m.addLoad({0, Dof::uy, 5.0});
  return std::move(bench.model);
}

/// K summed element by element into a dense matrix, free dofs only: the reference the
/// assembler's pattern and places must reproduce.
Eigen::MatrixXd denseStiffness(const Model& model, const DofMap& dofs) {
  const int nf = dofs.freeCount();
  Eigen::MatrixXd K = Eigen::MatrixXd::Zero(nf, nf);
  for (const auto& e : model.elements()) {
    const ElementMatrix k = e->stiffness();
    const auto d = e->dofs();
    for (int b = 0; b < int(d.size()); ++b)
      for (int a = 0; a < int(d.size()); ++a) {
        const int row = dofs.equation(d[a]), col = dofs.equation(d[b]);
        if (dofs.isFree(row) && dofs.isFree(col) && k(a, b) != 0) K(row, col) += k(a, b);
      }
  }
  return K;
}

/// Everything the passes produce for one model, to compare across part counts.
struct Passes {
  SparseMatrix K, M, coupling;  // coupling: K without its exact zeros
  Eigen::VectorXd loads, reactionForces;
  std::vector<SideRotations> hinges;
};

Passes runPasses(const Model& model) {
  const DofMap dofs(model);
  Passes out;
  std::tie(out.K, out.M) =
      SparseAssembler(model, dofs).assemble(MatrixKind::stiffness, MatrixKind::mass);
  out.coupling = out.K;
  dropExactZeros(out.coupling);
  out.loads = loadVector(model, dofs);
  Eigen::VectorXd u(dofs.size());
  for (int i = 0; i < u.size(); ++i) u[i] = std::sin(0.37 * i) * 1e-3;  // any displacement
  out.reactionForces = constrainedElementForces(model, dofs, u);
  NodalField field = NodalField::Zero(model.nodeCount(), kDofKinds);
  for (int eq = 0; eq < dofs.size(); ++eq)
    field(dofs.dofOf(eq).node, dofIndex(dofs.dofOf(eq).dof)) = u[eq];
  out.hinges = hingeRotations({model, field});
  return out;
}

bool sameBits(const SparseMatrix& a, const SparseMatrix& b) {
  return a.nonZeros() == b.nonZeros() &&
         std::equal(a.outerIndexPtr(), a.outerIndexPtr() + a.cols() + 1, b.outerIndexPtr()) &&
         std::equal(a.innerIndexPtr(), a.innerIndexPtr() + a.nonZeros(), b.innerIndexPtr()) &&
         std::equal(a.valuePtr(), a.valuePtr() + a.nonZeros(), b.valuePtr());
}

}  // namespace

TEST_CASE("parts: one per core this process may use, at most one per 50 000 items") {
  {
    const ThreadsSetting three("3");
    CHECK(partsFor(150000) == 3);
    CHECK(partsFor(149999) == 2);
    CHECK(partsFor(10) == 1);
    CHECK(partsFor(0) == 1);
  }
  {
    const ThreadsSetting one("1");
    CHECK(partsFor(1000000) == 1);
  }
  CHECK(evenRanges(10, 3) == std::vector<int>{0, 3, 6, 10});
  CHECK(evenRanges(0, 2) == std::vector<int>{0, 0, 0});
}

TEST_CASE("the assembled K is the element matrices summed dof by dof (pattern and places)") {
  // A short line: one part, so this checks the node-by-node pattern and the block offsets,
  // including a node whose dofs are all held (no column) and a spring's far-off entries.
  const std::unique_ptr<Model> model = awkwardLine(40);
  const DofMap dofs(*model);
  const SparseMatrix K = SparseAssembler(*model, dofs).assemble(MatrixKind::stiffness);
  const Eigen::MatrixXd reference = denseStiffness(*model, dofs);
  CHECK(Eigen::MatrixXd(K) == reference);  // the same sums in the same order: exact
  // The pattern holds every dof pair of two nodes sharing an element, and nothing else.
  CHECK(K.nonZeros() > (reference.array() != 0).count());
  CHECK(K.coeff(dofs.equation(3, Dof::uy), dofs.equation(37, Dof::uy)) == -2e5);
}

TEST_CASE("passes in three parts give the same bits as in one") {
  // 150 000 elements: three parts when three are allowed, each over 50 000.
  const std::unique_ptr<Model> model = awkwardLine(150000);
  const Passes one = [&] {
    const ThreadsSetting setting("1");
    return runPasses(*model);
  }();
  const Passes three = [&] {
    const ThreadsSetting setting("3");
    return runPasses(*model);
  }();
  CHECK(sameBits(one.K, three.K));
  CHECK(sameBits(one.M, three.M));
  CHECK(sameBits(one.coupling, three.coupling));
  // Without its exact zeros K is the same matrix: every diagonal entry kept, no other zero.
  CHECK(one.coupling.nonZeros() < one.K.nonZeros());
  CHECK((Eigen::MatrixXd(one.coupling.topLeftCorner(3000, 3000)) ==
         Eigen::MatrixXd(one.K.topLeftCorner(3000, 3000))));
  int zerosOffDiagonal = 0, diagonal = 0;
  for (int col = 0; col < one.coupling.outerSize(); ++col)
    for (SparseMatrix::InnerIterator it(one.coupling, col); it; ++it) {
      diagonal += it.row() == col;
      zerosOffDiagonal += it.row() != col && it.value() == 0;
    }
  CHECK(diagonal == one.coupling.cols());
  CHECK(zerosOffDiagonal == 0);
  CHECK(one.loads.size() == three.loads.size());
  CHECK(std::equal(one.loads.begin(), one.loads.end(), three.loads.begin()));
  CHECK(std::equal(one.reactionForces.begin(), one.reactionForces.end(),
                   three.reactionForces.begin()));
  REQUIRE(one.hinges.size() == 1);
  REQUIRE(three.hinges.size() == 1);
  CHECK(three.hinges[0].node == 6);
  CHECK(*one.hinges[0].left == *three.hinges[0].left);
  CHECK(*one.hinges[0].right == *three.hinges[0].right);

  // The constrained forces are the full element forces' entries at the constrained dofs
  // (the same elements summed in the same order).
  const DofMap dofs(*model);
  Eigen::VectorXd u(dofs.size());
  for (int i = 0; i < u.size(); ++i) u[i] = std::sin(0.37 * i) * 1e-3;
  const Eigen::VectorXd all = elementForces(*model, dofs, u);
  CHECK(std::equal(three.reactionForces.begin(), three.reactionForces.end(),
                   all.tail(dofs.constrainedCount()).begin()));
}

TEST_CASE("results side by side: a loop's results in order, and the first failing item's error") {
  // Each item a sum of its own (the reference: the same sums in a loop on this thread).
  const auto item = [](int i) {
    double sum = 0;
    for (int k = 1; k <= 1000 * (i % 7 + 1); ++k) sum += 1.0 / (k + i);
    return sum;
  };
  std::vector<double> loop;
  for (int i = 0; i < 40; ++i) loop.push_back(item(i));
  for (const int workers : {1, 2, 3}) {
    CAPTURE(workers);
    std::vector<int> workerSeen(40, -1);
    const std::vector<double> sideBySide = resultsSideBySide(40, workers, [&](int i, int worker) {
      workerSeen[std::size_t(i)] = worker;
      return item(i);
    });
    CHECK(sideBySide == loop);  // bit for bit
    CHECK(std::all_of(workerSeen.begin(), workerSeen.end(),
                      [&](int w) { return w >= 0 && w < workers; }));
    // Items 9, 12 and 30 throw: the loop would throw 9's, after every item before it ran.
    std::vector<char> ran(40, 0);
    try {
      resultsSideBySide(40, workers, [&](int i, int) {
        ran[std::size_t(i)] = 1;
        if (i == 9 || i == 12 || i == 30) throw std::runtime_error(std::to_string(i));
        return item(i);
      });
      FAIL("no error raised");
    } catch (const std::runtime_error& e) {
      CHECK(std::string(e.what()) == "9");
    }
    CHECK(std::all_of(ran.begin(), ran.begin() + 10, [](char r) { return r == 1; }));
  }
  CHECK(resultsSideBySide(0, 2, [](int, int) { return 1.0; }).empty());
}

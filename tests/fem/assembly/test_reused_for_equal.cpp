// Element quantities computed once for a run of equal elements: which beams are equal, and
// K, M and the load vector of a line whose runs are broken (a hinge, another section, another
// span load, a spring) equal to the element matrices and loads summed one by one.
#include <doctest/doctest.h>

#include <memory>

#include "elements/Beam.hpp"
#include "elements/Spring.hpp"
#include "fem/assembly/Assembly.hpp"
#include "fem/assembly/BandAssembly.hpp"
#include "fem/model/DofMap.hpp"
#include "fem/model/Model.hpp"
#include "tests/Helpers.hpp"

using namespace beamrotor;
using namespace beamrotor::test;

namespace {

/// A uniform line of 12 beams whose runs are broken: beam 3 hinged at its end, beams 8 and 9
/// under other span loads; and a grounded spring.
struct BrokenRuns {
  Model model;
  Line line;
  BrokenRuns() {
    const auto sec = steelCircle(0.05);
    line = uniformBeam(model, 3.0, sec, 12);
    clamp(model, "root", line.nodes.front(), DofSet::planar());
    for (Beam* b : line.beams) b->setDistributedLoad(Eigen::Vector3d(0, -100, 0));
    line.beams[3]->release(1, Dof::rz);
    line.beams[8]->setDistributedLoad(Eigen::Vector3d(0, -250, 0));
    line.beams[9]->setDistributedLoad(Eigen::Vector3d(0, -100, 0), Eigen::Vector3d(0, -400, 0));
    model.addElement(std::make_unique<Spring>(NodeDof{line.nodes[7], Dof::uy}, 3e5));
  }
};

/// One kind of element matrix summed element by element into a dense matrix (free dofs).
Eigen::MatrixXd summed(const Model& model, const DofMap& dofs, MatrixKind kind) {
  const int nf = dofs.freeCount();
  Eigen::MatrixXd A = Eigen::MatrixXd::Zero(nf, nf);
  for (const auto& e : model.elements()) {
    const ElementMatrix m = elementMatrix(*e, kind);
    const auto d = e->dofs();
    for (int b = 0; b < m.cols(); ++b)
      for (int a = 0; a < m.rows(); ++a) {
        const int row = dofs.equation(d[a]), col = dofs.equation(d[b]);
        if (dofs.isFree(row) && dofs.isFree(col)) A(row, col) += m(a, b);
      }
  }
  return A;
}

}  // namespace

TEST_SUITE("reused for equal elements") {
  TEST_CASE("which beams are equal") {
    const BrokenRuns r;
    const auto& b = r.line.beams;
    CHECK(b[0]->sameMatricesAs(*b[1]));
    CHECK(b[10]->sameMatricesAs(*b[11]));
    CHECK_FALSE(b[2]->sameMatricesAs(*b[3]));  // hinged end
    CHECK_FALSE(b[3]->sameMatricesAs(*b[4]));  // and back to plain
    CHECK(b[4]->sameMatricesAs(*b[5]));
    CHECK_FALSE(b[7]->sameMatricesAs(*b[8]));  // span load
    CHECK_FALSE(b[8]->sameMatricesAs(*b[9]));  // linearly varying span load
    const Element& spring = *r.model.elements().back();
    CHECK_FALSE(b[7]->sameMatricesAs(spring));
    CHECK_FALSE(spring.sameMatricesAs(*b[7]));  // springs never say so
    // Another section object: not known to be equal (its values are not compared).
    Model other;
    const Line twin = uniformBeam(other, 3.0, steelCircle(0.05), 12);
    CHECK_FALSE(b[0]->sameMatricesAs(*twin.beams[0]));
  }

  TEST_CASE("K, M and the loads equal the element quantities summed one by one") {
    const BrokenRuns r;
    const DofMap dofs(r.model);
    const auto [K, M] =
        SparseAssembler(r.model, dofs).assemble(MatrixKind::stiffness, MatrixKind::mass);
    // Equal to the last bit: each entry the same sum of the same numbers in the same order.
    CHECK(Eigen::MatrixXd(K) == summed(r.model, dofs, MatrixKind::stiffness));
    CHECK(Eigen::MatrixXd(M) == summed(r.model, dofs, MatrixKind::mass));
    const int kd = stiffnessBand(r.model, dofs).value();
    const SymmetricBand band = assembleBand(r.model, dofs, MatrixKind::stiffness, kd);
    const Eigen::MatrixXd dense = summed(r.model, dofs, MatrixKind::stiffness);
    for (int j = 0; j < band.size(); ++j)
      for (int i = j; i < band.size() && i <= j + kd; ++i) CHECK(band.lower(i, j) == dense(j, i));
    Eigen::VectorXd f = Eigen::VectorXd::Zero(dofs.size());
    for (const auto& e : r.model.elements()) {
      const ElementVector fe = e->load();
      const auto d = e->dofs();
      for (int a = 0; a < fe.size(); ++a) f[dofs.equation(d[a])] += fe[a];
    }
    CHECK(loadVector(r.model, dofs) == f);
  }
}

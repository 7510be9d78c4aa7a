#include "fem/rotor/GravityLoads.hpp"

#include <cmath>
#include <string>
#include <utility>

#include "fem/model/RotorElement.hpp"
#include "fem/rotor/BearingSupports.hpp"
#include "fem/rotor/RotorSystem.hpp"
#include "fem/solvers/Errors.hpp"
#include "fem/solvers/SparseLU.hpp"
#include "fem/solvers/Tolerances.hpp"

namespace beamrotor {

namespace {

/// A restricted to the equations `index` keeps (renumbered).
SparseMatrix restrictedTo(const SparseMatrix& A, const std::vector<int>& index, int size) {
  std::vector<Eigen::Triplet<double>> t;
  for (int col = 0; col < A.outerSize(); ++col)
    for (SparseMatrix::InnerIterator it(A, col); it; ++it)
      if (index[it.row()] >= 0 && index[col] >= 0)
        t.emplace_back(index[it.row()], index[col], it.value());
  SparseMatrix out(size, size);
  out.setFromTriplets(t.begin(), t.end());
  return out;
}

}  // namespace

int GravityLoads::largestSag() const {
  int worst = -1;
  for (int i = 0; i < int(nodes.size()); ++i)
    if (worst < 0 || std::hypot(uy[i], uz[i]) > std::hypot(uy[worst], uz[worst])) worst = i;
  return worst;
}

GravityLoads solveGravityLoads(const Model& model, const Eigen::Vector3d& gravity,
                               BearingSupport support, double speed) {
  const RotorSystem system(model);
  const DofMap& dofs = system.dofs();
  const int n = system.size();
  const BearingSupports supports = bearingSupports(system);

  // 1. The weight: f = M a, a = g on every translation.
  Eigen::VectorXd a = Eigen::VectorXd::Zero(n);
  for (int eq = 0; eq < n; ++eq) {
    const Dof d = dofs.dofOf(eq).dof;
    if (d == Dof::ux) a[eq] = gravity.x();
    if (d == Dof::uy) a[eq] = gravity.y();
    if (d == Dof::uz) a[eq] = gravity.z();
  }
  const Eigen::VectorXd f = system.mass() * a;
  GravityLoads out;
  for (int eq = 0; eq < n; ++eq) {
    const Dof d = dofs.dofOf(eq).dof;
    if (d == Dof::ux || d == Dof::uy || d == Dof::uz) out.weight[int(d)] += f[eq];
  }

  // 2. K u = f, with the bearings pinned or as themselves.
  const bool rigid = support == BearingSupport::rigid;
  const SparseMatrix K = rigid ? supports.shaft : system.stiffness(speed);
  const std::vector<int> index = numberingWithout(n, rigid ? supports.equations
                                                           : std::vector<int>{});
  const int kept = n - (rigid ? int(supports.equations.size()) : 0);
  const SparseMatrix Kkept = restrictedTo(K, index, kept);
  SparseLU lu;
  lu.compute(Kkept);
  if (!lu.healthy(kSingularRcond))
    throw SolveError("bearing loads: the rotor is not held by its bearings (and supports): " +
                     std::string(rigid ? "pinned" : "elastic") +
                     " bearings leave it free to move; a rotor needs two bearings or more");
  Eigen::VectorXd fKept(kept);
  for (int eq = 0; eq < n; ++eq)
    if (index[eq] >= 0) fKept[index[eq]] = f[eq];
  const Eigen::VectorXd uKept = lu.solve(fKept);
  Eigen::VectorXd u = Eigen::VectorXd::Zero(n);
  for (int eq = 0; eq < n; ++eq)
    if (index[eq] >= 0) u[eq] = uKept[index[eq]];

  // 3. Bearing forces on the shaft: pinned, the reaction K u - f at its equations (the first
  // bearing at a node takes the node's); elastic, -K_b u_b of each bearing.
  const Eigen::VectorXd pinReaction = K * u - f;
  std::vector<bool> taken(n, false);
  for (int i = 0; i < int(model.elements().size()); ++i) {
    const SpeedDependentElement* b = asBearing(*model.elements()[i]);
    if (!b) continue;
    const auto d = b->dofs();  // uy, uz
    BearingForce force{i, d[0].node, model.nodes()[d[0].node].x(), 0, 0};
    const int y = dofs.equation(d[0]), z = dofs.equation(d[1]);
    if (rigid) {
      for (auto [eq, component] : {std::pair{y, &force.fy}, std::pair{z, &force.fz}})
        if (dofs.isFree(eq) && !taken[eq]) {
          *component = pinReaction[eq];
          taken[eq] = true;
        }
    } else {
      const ElementMatrix k = b->stiffnessAt(speed);  // over (uy, uz)
      const double uy = dofs.isFree(y) ? u[y] : 0, uz = dofs.isFree(z) ? u[z] : 0;
      force.fy = -(k(0, 0) * uy + k(0, 1) * uz);
      force.fz = -(k(1, 0) * uy + k(1, 1) * uz);
    }
    out.bearings.push_back(force);
  }

  // 4. The sag at every node carrying uy and uz.
  for (int node = 0; node < int(model.nodes().size()); ++node) {
    const int y = dofs.equation(node, Dof::uy), z = dofs.equation(node, Dof::uz);
    if (y < 0 || z < 0) continue;
    out.nodes.push_back(node);
    out.x.push_back(model.nodes()[node].x());
    out.uy.push_back(dofs.isFree(y) ? u[y] : 0);
    out.uz.push_back(dofs.isFree(z) ? u[z] : 0);
  }
  return out;
}

}  // namespace beamrotor

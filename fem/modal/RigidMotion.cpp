#include "fem/modal/RigidMotion.hpp"

#include <cmath>
#include <cstdio>

namespace beamrotor {

namespace {

/// The six rigid motions over the free dofs (columns: translations x y z, rotations about x y
/// z through the nodes' mean place).
Eigen::MatrixXd rigidMotions(const Model& model, const DofMap& dofs) {
  Eigen::Vector3d centre = Eigen::Vector3d::Zero();
  for (const auto& x : model.nodes()) centre += x;
  if (!model.nodes().empty()) centre /= double(model.nodes().size());
  Eigen::MatrixXd R = Eigen::MatrixXd::Zero(dofs.freeCount(), 6);
  for (int eq = 0; eq < dofs.freeCount(); ++eq) {
    const NodeDof& d = dofs.dofOf(eq);
    const int k = dofIndex(d.dof);
    R(eq, k) = 1;
    if (k >= 3) continue;
    const Eigen::Vector3d r = model.nodes()[d.node] - centre;
    for (int a = 0; a < 3; ++a) R(eq, 3 + a) = Eigen::Vector3d::Unit(a).cross(r)[k];
  }
  return R;
}

/// The shares from R (rigid motions), MR = M R, the shapes and M times the shapes.
std::vector<RigidShares> sharesOf(const Eigen::MatrixXd& R, const Eigen::MatrixXd& MR,
                                  const Eigen::MatrixXd& shapes, const Eigen::MatrixXd& Mshapes) {
  const Eigen::MatrixXd G = R.transpose() * MR;       // r_i' M r_j
  const Eigen::MatrixXd L = MR.transpose() * shapes;  // r_i' M phi
  std::vector<int> moving;                            // translations some free dof carries
  for (int k = 0; k < 3; ++k)
    if (G(k, k) > 0) moving.push_back(k);
  const Eigen::MatrixXd Gtt = G(moving, moving);
  const auto solver = Gtt.ldlt();
  std::vector<RigidShares> out(shapes.cols(), RigidShares{});
  for (int m = 0; m < int(shapes.cols()); ++m) {
    const double norm = shapes.col(m).dot(Mshapes.col(m));
    if (!(norm > 0)) continue;
    for (int k : moving) out[m][k] = L(k, m) * L(k, m) / (G(k, k) * norm);
  }
  for (int a = 3; a < 6; ++a) {
    if (!(G(a, a) > 0)) continue;
    // The rotation less its M-projection on the translations.
    Eigen::VectorXd c = Eigen::VectorXd::Zero(Eigen::Index(moving.size()));
    if (!moving.empty()) c = solver.solve(Eigen::VectorXd(G(moving, a)));
    const double own =
        G(a, a) - (moving.empty() ? 0.0 : c.dot(Eigen::VectorXd(G(moving, a))));
    if (!(own > 1e-12 * G(a, a))) continue;  // a rotation that is a translation here
    for (int m = 0; m < int(shapes.cols()); ++m) {
      const double norm = shapes.col(m).dot(Mshapes.col(m));
      if (!(norm > 0)) continue;
      const double part = L(a, m) - (moving.empty() ? 0.0 : c.dot(Eigen::VectorXd(L(moving, m))));
      out[m][a] = part * part / (own * norm);
    }
  }
  return out;
}

}  // namespace

std::vector<RigidShares> rigidMotionShares(const Model& model, const DofMap& dofs,
                                           const SparseMatrix& M, const Eigen::MatrixXd& shapes) {
  const Eigen::MatrixXd R = rigidMotions(model, dofs);
  return sharesOf(R, M * R, shapes, M * shapes);
}

RigidShares rigidMotionShares(const Model& model, const NodalField& shape) {
  const DofMap dofs(model);
  Eigen::MatrixXd phi(dofs.freeCount(), 1);
  Eigen::VectorXd unit(dofs.freeCount());  // the diagonal mass: 1 on translations
  for (int eq = 0; eq < dofs.freeCount(); ++eq) {
    const NodeDof& d = dofs.dofOf(eq);
    phi(eq, 0) = shape(d.node, dofIndex(d.dof));
    unit[eq] = dofIndex(d.dof) < 3 ? 1.0 : 0.0;
  }
  const Eigen::MatrixXd R = rigidMotions(model, dofs);
  return sharesOf(R, unit.asDiagonal() * R, phi, unit.asDiagonal() * phi).front();
}

std::string describeRigidMotion(const RigidShares& shares, const std::string& of) {
  static const char* const kNames[6] = {"sway ux",         "vertical uy",     "sway uz",
                                        "rocking about x", "torsion about y", "rocking about z"};
  int best = 0;
  for (int k = 1; k < 6; ++k)
    if (shares[k] > shares[best]) best = k;
  if (!(shares[best] >= 0.05)) {
    std::string out = "local (no rigid motion over 5 % of the ";
    out += of;
    out += ")";
    return out;
  }
  char percent[16];
  std::snprintf(percent, sizeof percent, "%.0f", 100 * shares[best]);
  std::string out = kNames[best];
  out += ", ";
  out += percent;
  out += " % of the ";
  out += of;
  return out;
}

}  // namespace beamrotor

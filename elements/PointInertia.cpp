#include "elements/PointInertia.hpp"

#include <cmath>
#include <stdexcept>

namespace beamrotor {

PointInertia::PointInertia(int node, DofSet carried, double m, double Jp, double Jd,
                           const Eigen::Vector3d& axis)
    : m_(m), Jp_(Jp), Jd_(Jd), axis_(axis.normalized()) {
  for (double v : {m, Jp, Jd})
    if (!std::isfinite(v) || v < 0)
      throw std::invalid_argument("mass and moments of inertia must be finite and >= 0");
  if (!(axis.norm() > 0)) throw std::invalid_argument("inertia axis must be non-zero");
  for (Dof d : kAllDofs)
    if (carried.contains(d)) dofs_.push_back({node, d});
}

ElementMatrix PointInertia::stiffness() const {
  return ElementMatrix::Zero(dofs_.size(), dofs_.size());
}

ElementMatrix PointInertia::mass() const {
  // Inertia tensor of an axisymmetric body: Jd I + (Jp - Jd) a a^T.
  const Eigen::Matrix3d J =
      Jd_ * Eigen::Matrix3d::Identity() + (Jp_ - Jd_) * axis_ * axis_.transpose();
  const int n = int(dofs_.size());
  ElementMatrix M = ElementMatrix::Zero(n, n);
  for (int a = 0; a < n; ++a)
    for (int b = 0; b < n; ++b) {
      const Dof da = dofs_[a].dof, db = dofs_[b].dof;
      if (!isRotation(da) && da == db) M(a, b) = m_;
      if (isRotation(da) && isRotation(db)) M(a, b) = J(dofIndex(da) - 3, dofIndex(db) - 3);
    }
  return M;
}

}  // namespace beamrotor

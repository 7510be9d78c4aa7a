#include "elements/PointInertia.hpp"

#include <cmath>
#include <stdexcept>

namespace beamrotor {

PointInertia::PointInertia(int node, DofSet carried, double m, double Jp, double Jd,
                           const Eigen::Vector3d& axis)
    : node_(node), m_(m), Jp_(Jp), Jd_(Jd), axis_(axis.normalized()) {
  for (double v : {m, Jp, Jd})
    if (!std::isfinite(v) || v < 0)
      throw std::invalid_argument("mass and moments of inertia must be finite and >= 0");
  if (!(axis.norm() > 0)) throw std::invalid_argument("inertia axis must be non-zero");
  for (Dof d : kAllDofs)
    if (carried.contains(d)) codes_[count_++] = elementDofCode(0, d);
}

ElementMatrix PointInertia::stiffness() const {
  return ElementMatrix::Zero(count_, count_);
}

ElementMatrix PointInertia::mass() const {
  // Inertia tensor of an axisymmetric body: Jd I + (Jp - Jd) a a^T.
  const Eigen::Matrix3d J =
      Jd_ * Eigen::Matrix3d::Identity() + (Jp_ - Jd_) * axis_ * axis_.transpose();
  const ElementDofs d = dofs();
  const int n = count_;
  ElementMatrix M = ElementMatrix::Zero(n, n);
  for (int a = 0; a < n; ++a)
    for (int b = 0; b < n; ++b) {
      const Dof da = d[a].dof, db = d[b].dof;
      if (!isRotation(da) && da == db) M(a, b) = m_;
      if (isRotation(da) && isRotation(db)) M(a, b) = J(dofIndex(da) - 3, dofIndex(db) - 3);
    }
  return M;
}

ElementMatrix PointInertia::gyroscopic() const {
  // A body spinning at Omega about its axis a carries H = Jp Omega a; a small rotation theta
  // turns a into a + theta x a, so dH/dt = Jp Omega theta' x a = -Jp Omega [a]x theta': the
  // moment needed is G theta' with G = -Jp [a]x (Lalanne and Ferraris, Rotordynamics
  // Prediction in Engineering, 1998, ch. 2, in vector form).
  const Eigen::Matrix3d G = -Jp_ * (Eigen::Matrix3d() << 0, -axis_.z(), axis_.y(),  //
                                    axis_.z(), 0, -axis_.x(),                        //
                                    -axis_.y(), axis_.x(), 0)
                                       .finished();
  const ElementDofs d = dofs();
  const int n = count_;
  ElementMatrix out = ElementMatrix::Zero(n, n);
  for (int a = 0; a < n; ++a)
    for (int b = 0; b < n; ++b)
      if (isRotation(d[a].dof) && isRotation(d[b].dof))
        out(a, b) = G(dofIndex(d[a].dof) - 3, dofIndex(d[b].dof) - 3);
  if (out.isZero(0)) return {};
  return out;
}

}  // namespace beamrotor

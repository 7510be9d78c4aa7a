// A rigid body lumped at a node: mass m on the translations and the inertia tensor of a body
// symmetric about `axis` (polar moment Jp about it, transverse moment Jd about any
// perpendicular axis through the node) on the rotations. A point mass is Jp = Jd = 0.
#pragma once

#include <array>
#include <cstdint>

#include "fem/model/Element.hpp"

namespace beamrotor {

class PointInertia : public Element {
 public:
  /// m in kg, Jp and Jd in kg m^2 about the node; axis in global coordinates.
  PointInertia(int node, DofSet carried, double m, double Jp = 0, double Jd = 0,
               const Eigen::Vector3d& axis = Eigen::Vector3d::UnitX());

  ElementDofs dofs() const override { return {{node_, node_}, codes_.data(), count_}; }
  ElementMatrix stiffness() const override;
  ElementMatrix mass() const override;
  /// Gyroscopic matrix per unit spin speed about `axis` (kg m^2), on the carried rotations:
  /// -Jp [axis]x, i.e. Jp [0 1; -1 0] on (ry, rz) for axis x. Empty when Jp = 0 or fewer than
  /// two rotations are carried.
  ElementMatrix gyroscopic() const override;
  std::string kind() const override { return "inertia"; }

  double m() const { return m_; }
  double Jp() const { return Jp_; }
  double Jd() const { return Jd_; }
  const Eigen::Vector3d& axis() const { return axis_; }

 private:
  int node_;
  std::array<std::uint8_t, kDofKinds> codes_{};
  int count_ = 0;
  double m_, Jp_, Jd_;
  Eigen::Vector3d axis_;
};

}  // namespace beamrotor

// Linear springs (with optional viscous dampers) on one dof kind: grounded (one node to the
// fixed frame) or between two nodes. Translational (N/m, N s/m) or rotational (N m/rad,
// N m s/rad) according to the dof.
#pragma once

#include <array>

#include "fem/model/Element.hpp"

namespace beamrotor {

class Spring : public Element {
 public:
  /// Grounded spring on dof `a`.
  Spring(NodeDof a, double stiffness, double damping = 0);
  /// Spring between dof `a` and dof `b` (same kind on two nodes, usually).
  Spring(NodeDof a, NodeDof b, double stiffness, double damping = 0);

  ElementDofs dofs() const override { return {nodes_, codes_.data(), count_}; }
  ElementMatrix stiffness() const override { return pattern(k_); }
  ElementMatrix damping() const override { return c_ != 0 ? pattern(c_) : ElementMatrix{}; }
  std::string kind() const override { return count_ == 1 ? "spring-grounded" : "spring"; }
  double stiffnessValue() const { return k_; }

 private:
  ElementMatrix pattern(double value) const;

  std::array<int, 2> nodes_{};
  std::array<std::uint8_t, 2> codes_{};
  int count_ = 0;
  double k_ = 0, c_ = 0;
};

}  // namespace beamrotor

#include "elements/Spring.hpp"

#include <cmath>
#include <stdexcept>

namespace beamrotor {

namespace {
void check(double k, double c) {
  if (!std::isfinite(k) || k < 0) throw std::invalid_argument("spring stiffness must be >= 0");
  if (!std::isfinite(c) || c < 0) throw std::invalid_argument("damping must be >= 0");
}
}  // namespace

Spring::Spring(NodeDof a, double stiffness, double damping)
    : nodes_{a.node, a.node},
      codes_{elementDofCode(0, a.dof)},
      count_(1),
      k_(stiffness),
      c_(damping) {
  check(k_, c_);
}

Spring::Spring(NodeDof a, NodeDof b, double stiffness, double damping)
    : nodes_{a.node, b.node},
      codes_{elementDofCode(0, a.dof), elementDofCode(1, b.dof)},
      count_(2),
      k_(stiffness),
      c_(damping) {
  check(k_, c_);
  if (a == b) throw std::invalid_argument("a two-node spring needs two different dofs");
}

ElementMatrix Spring::pattern(double value) const {
  ElementMatrix m(count_, count_);
  if (count_ == 1)
    m(0, 0) = value;
  else
    m << value, -value, -value, value;
  return m;
}

}  // namespace beamrotor

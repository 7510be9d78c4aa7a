#include "elements/GearMesh.hpp"

#include <cmath>
#include <stdexcept>

namespace beamrotor {

GearMesh::GearMesh(int a, int b, double ratio, double stiffness, double damping)
    : nodes_{a, b},
      codes_{elementDofCode(0, Dof::rx), elementDofCode(1, Dof::rx)},
      ratio_(ratio),
      k_(stiffness),
      c_(damping) {
  if (!std::isfinite(ratio) || ratio <= 0) throw std::invalid_argument("gear ratio must be > 0");
  if (!std::isfinite(k_) || k_ <= 0) throw std::invalid_argument("mesh stiffness must be > 0");
  if (!std::isfinite(c_) || c_ < 0) throw std::invalid_argument("mesh damping must be >= 0");
  if (a == b) throw std::invalid_argument("a gear mesh joins two different nodes");
}

ElementMatrix GearMesh::pattern(double value) const {
  ElementMatrix m(2, 2);
  m << value, -value * ratio_, -value * ratio_, value * ratio_ * ratio_;
  return m;
}

}  // namespace beamrotor

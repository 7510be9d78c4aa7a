// Elements whose stiffness and damping depend on the spin speed (fluid-film bearings, seals):
// the rotor analyses re-evaluate them at every speed; the other analyses see them at rest.
#pragma once

#include "fem/model/Element.hpp"

namespace beamrotor {

/// uy and uz at `node`: the dofs a bearing acts on.
inline ElementDofs lateralDofs(int node) {
  static constexpr std::uint8_t codes[] = {elementDofCode(0, Dof::uy), elementDofCode(0, Dof::uz)};
  return {{node, node}, codes, 2};
}

class SpeedDependentElement : public Element {
 public:
  /// Stiffness at spin speed Omega (rad/s), global frame, ordered as dofs(); may be
  /// non-symmetric (cross-coupled bearings).
  virtual ElementMatrix stiffnessAt(double speed) const = 0;
  /// Viscous damping at spin speed Omega (rad/s); empty when none.
  virtual ElementMatrix dampingAt(double speed) const = 0;

  /// At rest (Omega = 0): what statics and the non-rotating modal analysis use.
  ElementMatrix stiffness() const override { return stiffnessAt(0); }
  ElementMatrix damping() const override { return dampingAt(0); }
  /// Cross-coupled coefficients (k_yz != k_zy) are allowed even at rest.
  bool symmetricStiffness() const override { return false; }
};

}  // namespace beamrotor

// Elements whose stiffness and damping depend on the spin speed (fluid-film bearings, seals):
// the rotor analyses re-evaluate them at every speed; the other analyses see them at rest.
#pragma once

#include <complex>

#include "fem/model/Element.hpp"

namespace beamrotor {

/// uy and uz at `node`: the dofs a bearing acts on.
inline ElementDofs lateralDofs(int node) {
  static constexpr std::uint8_t codes[] = {elementDofCode(0, Dof::uy), elementDofCode(0, Dof::uz)};
  return {{node, node}, codes, 2};
}

/// What an element shows a motion q e^{lambda t}: real K and C whose K + lambda C is its
/// impedance at that lambda (whirl-dependent bearings, SpeedDependentElement::atEigenvalue).
struct EigenvalueMatrices {
  ElementMatrix stiffness, damping;  ///< damping empty when none
};

class SpeedDependentElement : public Element {
 public:
  /// Stiffness at spin speed Omega (rad/s), global frame, ordered as dofs(); may be
  /// non-symmetric (cross-coupled bearings).
  virtual ElementMatrix stiffnessAt(double speed) const = 0;
  /// Viscous damping at spin speed Omega (rad/s); empty when none.
  virtual ElementMatrix dampingAt(double speed) const = 0;

  /// Whether the coefficients depend on the motion's frequency as well as on the speed (a
  /// tilting-pad bearing, a table by whirl frequency): the damped modes then find each mode
  /// with the coefficients at its own eigenvalue (fem/rotor/WhirlIteration.hpp).
  virtual bool dependsOnWhirl() const { return false; }
  /// K and C at spin speed Omega (rad/s) seen by a motion e^{lambda t} (lambda in 1/s,
  /// Im lambda >= 0); without whirl dependence the speed's own (synchronous) set.
  virtual EigenvalueMatrices atEigenvalue(double speed, std::complex<double> lambda) const {
    (void)lambda;
    return {stiffnessAt(speed), dampingAt(speed)};
  }

  /// How many of dofs()' last entries are the element's own: dofs of a bearing's inner parts
  /// (a tilting pad's tilt) that no shaft element carries. The rotor analyses report the modes
  /// whose energy lies there as the bearing's own, apart from the rotor's.
  virtual int ownDofs() const { return 0; }

  /// At rest (Omega = 0): what statics and the non-rotating modal analysis use.
  ElementMatrix stiffness() const override { return stiffnessAt(0); }
  ElementMatrix damping() const override { return dampingAt(0); }
  /// Cross-coupled coefficients (k_yz != k_zy) are allowed even at rest.
  bool symmetricStiffness() const override { return false; }
};

}  // namespace beamrotor

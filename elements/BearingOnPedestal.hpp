// A bearing whose housing sits on a pedestal (or a foundation) instead of the fixed frame:
// the film (or the bearing's coefficients) acts between the journal and the housing, and the
// housing, a mass on its own stiffness and damping to the ground, moves. In series: a
// journal at u_s and a housing at u_p feel F_s = -K (u_s - u_p) - C (u_s' - u_p'), and the
// housing F_p = -F_s; the pedestal adds m_p u_p'' + C_p u_p' + K_p u_p to the housing's own
// equations (a PointInertia and grounded Springs at the housing's node, added beside this).
//
// Its dofs are the journal's uy, uz and the housing's uy, uz: the matrix is [B -B; -B B] for
// the bearing's B (stiffness or damping at the speed), kind "bearing-on-pedestal", so that
// the analyses that pin or replace a rotor's bearings (fem/rotor/BearingSupports.hpp: kind
// "bearing") do not take it for one.
#pragma once

#include "elements/Bearing.hpp"

namespace beamrotor {

class BearingOnPedestal : public SpeedDependentElement {
 public:
  /// The bearing between `journal` and `housing` (nodes with uy, uz), coefficients at speed.
  BearingOnPedestal(int journal, int housing, std::vector<double> speeds,
                    std::vector<BearingCoefficients> table);

  ElementDofs dofs() const override;
  ElementMatrix stiffnessAt(double speed) const override;
  ElementMatrix dampingAt(double speed) const override;
  std::string kind() const override { return "bearing-on-pedestal"; }
  int housing() const { return housing_; }  ///< the housing's node

  /// The film's coefficients by whirl as well (Bearing::setWhirlCoefficients).
  void setWhirlCoefficients(std::shared_ptr<const WhirlCoefficients> whirl) {
    film_.setWhirlCoefficients(std::move(whirl));
  }
  bool dependsOnWhirl() const override { return film_.dependsOnWhirl(); }
  EigenvalueMatrices atEigenvalue(double speed, std::complex<double> lambda) const override;

 private:
  Bearing film_;  ///< the coefficients, as a grounded bearing at the journal would have them
  int journal_, housing_;
};

}  // namespace beamrotor

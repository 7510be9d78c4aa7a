// A tilting-pad bearing's pads as a nonlinear film for the run-up (fem/runup/JournalFilm.hpp):
// the force of every pad's Reynolds film on the journal at its instantaneous position and
// velocity, each massless pad tilted where its film's moment about the pivot vanishes, with
// the same film, grid, cavitation and tilt root as the bearing's coefficients
// (elements/PadFilm.hpp, elements/TiltingPadBearing.hpp).
//
// Pad k (pivot at theta_k + the load angle in global axes, e_k towards it, t_k a quarter turn
// on, c_p = c_b / (1 - m)): the journal at u, moving at u', is at rho = u . e_k / c_p towards the
// pivot and approaches it at rho' = u' . e_k / c_p. The pad follows the journal: its tilt s
// (elements/TiltingPadBearing.hpp) is the root of the film's moment, f_k . t_k = 0, for the
// film at rho squeezed at rho' / Omega; moving across the pivot line the journal carries the
// pad with it (no relative velocity along t_k). So the pad pushes along e_k only,
//   F_k = mu Omega R^3 L / c_p^2 f(rho, rho' / Omega) e_k,
// a function of the journal's state alone. Its derivatives by the implicit-function theorem on
// the root (K, D the film's stiffness and damping in pad axes at the root, exact derivatives
// of the discrete film, elements/ReynoldsFilm.hpp):
//   -df/drho = K_ee - K_et K_te / K_tt,   -df/d(rho' / Omega) = D_ee - K_et D_te / K_tt,
// stiffness sum_k mu Omega R^3 L / c_p^3 k_k e_k e_k^T, damping sum_k mu R^3 L / c_p^3 c_k e_k e_k^T.
// At rest (rho' = 0) the stiffness is the bearing's static set (tiltingPadStaticStiffness);
// the damping is the pads' following damping, not the synchronous set's: the synchronous set
// lets each massless pad lag the journal through its own squeeze film (Z' = Z - Z t t^T Z / Z_tt
// at whirl = spin), which a tilt fixed by the journal's state alone cannot (docs/runup.md gives
// the difference on the test bearing). A pad the journal leaves (m + rho <= 0: its film no
// longer narrows towards the pivot, and a squeeze towards it is left out too) or whose film a
// receding squeeze opens (no root) carries nothing.
//
// Drag on the spin: each pad's film shears the journal by Couette's flow over the pad's whole arc
// and by its pressure flow, whose share is half the moment of the pad's force about the pad's
// centre of curvature (as for the plain journal, elements/PlainJournalBearing.hpp's
// journalDragTorque; the film's pressure integrated by parts over the arc, P = 0 at its edges):
//   T_k = mu Omega R^3 L / c_p int_arc dphi / H + (x_k x F_k) / 2,   x_k = c_p (m + rho, s),
// an unloaded pad's Couette part at s = 0.
//
// Cost: each call solves every pad's tilt by Newton from its last root (a film with its
// coefficients a Newton step); a call at the state of the last one returns its answer.
#pragma once

#include <mutex>
#include <optional>
#include <vector>

#include "elements/PadFilm.hpp"
#include "elements/PlainJournalBearing.hpp"
#include "elements/TiltingPadBearing.hpp"
#include "fem/runup/JournalFilm.hpp"

namespace beamrotor {

class TiltingPadJournalFilm : public JournalFilm {
 public:
  /// The journal's geometry and oil (`journal.clearance` the bearing clearance c_b; its load
  /// is not used: the load comes with each call), the pads, one pad's film grid, and the
  /// bearing's axes turned by `loadAngle` (rad) about +x (x_b -> y at 0).
  TiltingPadJournalFilm(const PlainJournal& journal, const TiltingPads& pads,
                        const ReynoldsGrid& grid, double loadAngle);
  /// Throws JournalLeftClearance when the journal reaches a pad, std::invalid_argument for a
  /// spin that is not positive (no film).
  FilmForce at(const Eigen::Vector2d& position, const Eigen::Vector2d& velocity,
               double speed) const override;
  /// Newton on the journal's position until the pads carry `load`, its Jacobian the film's
  /// stiffness, to 1e-12 of the load (tiltingPadPoint's equilibrium for a load along -x_b).
  Eigen::Vector2d equilibrium(const Eigen::Vector2d& load, double speed) const override;
  /// The pads' drag (see the header) at the state of at()'s last call at `position`, or at
  /// rest there; a zero `force` gives the Couette part alone (its slope in the speed).
  double dragTorque(const Eigen::Vector2d& position, const Eigen::Vector2d& force,
                    double speed) const override;
  double clearance() const override { return journal_.clearance; }

 private:
  /// One pad at the last call: its tilt root (none: unloaded) and force (N, along e_k).
  struct PadState {
    double rho = 0;
    std::optional<double> s;
    double force = 0;
  };
  FilmForce solve(const Eigen::Vector2d& position, const Eigen::Vector2d& velocity,
                  double speed) const;
  Eigen::Vector2d unit(double angle) const;

  PlainJournal journal_;
  TiltingPads pads_;
  double padClearance_ = 0;  ///< c_p
  std::vector<double> pivots_;  ///< global angles of the pivots
  mutable std::mutex mutex_;    ///< guards the pads' films and the memo
  mutable std::vector<PadFilm> films_;
  mutable std::vector<PadState> states_;
  mutable Eigen::Vector2d lastPosition_{0, 0}, lastVelocity_{0, 0};
  mutable double lastSpeed_ = -1;
  mutable FilmForce lastForce_;
};

}  // namespace beamrotor

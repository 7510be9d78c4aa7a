// A tilting-pad bearing's pads as a nonlinear film for the run-up (fem/runup/JournalFilm.hpp),
// each pad's tilt a degree of freedom of the film's own: the force of every pad's Reynolds film
// on the journal and its moment on the pad about the pivot at the journal's and the pads'
// instantaneous positions and velocities, with the same film, grid and cavitation as the
// bearing's coefficients (elements/PadFilm.hpp, elements/TiltingPadBearing.hpp).
//
// State (y, z, delta_1 .. delta_n): the journal's centre from the bearing's centre (m, global)
// and each pad's tilt about its pivot (rad, in the sense of rotation, as the rx dof of
// elements/TiltingPadFilm.hpp). Pad k (pivot at theta_k + the load angle in global axes, e_k
// towards it, t_k a quarter turn on, c_p = c_b / (1 - m)) sees the journal relative to its
// centre of curvature, w = B^T x (x = (y, z, delta_k), B = [e_k t_k; 0 -R], 3 x 2):
//   rho = e_k . u / c_p,   s = (t_k . u - R delta_k) / c_p,
// moving at w' / (c_p Omega), the film H = 1 - (m + rho) cos(phi) - s sin(phi) squeezed by that
// velocity (elements/ReynoldsFilm.hpp). Its force f (pad axes, over mu Omega R^3 L / c_p^2)
// acts on the journal and, by virtual work on w, on the pad as -R f . t_k: the generalised
// forces on x are B f scaled, their derivatives
//   stiffness B K B^T mu Omega R^3 L / c_p^3,   damping B C B^T mu R^3 L / c_p^3,
// K, C the film's own derivatives in pad axes (exact for the discrete film, the perturbed
// Reynolds equation on the film's one factorisation). At the bearing's equilibrium (the film at
// rest, each pad where f . t_k = 0) these are TiltingPadFilm's K and C blocks; condensing the
// massless pads at whirl = spin gives the synchronous set (Lund 1964).
//
// A pad whose film diverges everywhere (the journal has left it, or a receding squeeze opens the
// film) carries nothing: force, moment and derivatives 0. A massless pad then has nothing on its
// tilt: its tangent holds a placeholder damping of 1e-6 mu R^5 L / c_p^3 on the tilt alone
// (not in the force: the step's solution is unchanged), so the step's matrix stays regular and
// the pad keeps its tilt rate until its film takes hold again. A film that closes on a pad (the
// journal or the pad's edge touching) throws JournalLeftClearance.
//
// Drag on the spin: each pad's film shears the journal by Couette's flow over the pad's whole
// arc and by its pressure flow, whose share is half the moment of the pad's force about the
// pad's centre of curvature (as for the plain journal, elements/PlainJournalBearing.hpp's
// journalDragTorque; the film's pressure integrated by parts over the arc, P = 0 at its edges):
//   T_k = mu Omega R^3 L / c_p int_arc dphi / H + (x_k x F_k) / 2,   x_k = c_p (m + rho, s).
//
// Start: restState puts the journal and the pads at the bearing's own equilibrium
// (tiltingPadPoint: each pad on its tilt root); a pad unloaded there at the tilt where its film
// just stops converging (s = (m + rho) tan(phi_trailing)).
//
// Cost: each call solves every pad's film once with its coefficients (one factorisation, four
// back-substitutions); a call at the state of the last one returns its answer.
#pragma once

#include <mutex>
#include <string>
#include <vector>

#include "elements/PadFilm.hpp"
#include "elements/PlainJournalBearing.hpp"
#include "elements/TiltingPadBearing.hpp"
#include "fem/runup/JournalFilm.hpp"

namespace beamrotor {

class TiltingPadJournalFilm : public BearingFilm {
 public:
  /// The journal's geometry and oil (`journal.clearance` the bearing clearance c_b; its load
  /// is not used: the load comes with restState), the pads, one pad's film grid, and the
  /// bearing's axes turned by `loadAngle` (rad) about +x (x_b -> y at 0).
  TiltingPadJournalFilm(const PlainJournal& journal, const TiltingPads& pads,
                        const ReynoldsGrid& grid, double loadAngle);
  int ownDofs() const override { return pads_.count; }
  /// Throws JournalLeftClearance when a film closes on a pad, std::invalid_argument for a
  /// spin that is not positive (no film) or a state not of size 2 + pads.
  FilmLoad loadAt(const Eigen::VectorXd& state, const Eigen::VectorXd& rate,
                  double speed) const override;
  /// The bearing's equilibrium carrying `load` (along the bearing's -x_b, or zero): the
  /// journal's place and every pad's tilt. Throws std::invalid_argument for a load along
  /// another line or one the pads cannot carry.
  Eigen::VectorXd restState(const Eigen::Vector2d& load, double speed) const override;
  /// The pads' drag (see the header) at the state of loadAt's last call at `state`, or at
  /// rest there; a zero `force` gives the Couette part alone (its slope in the speed).
  double dragTorqueAt(const Eigen::VectorXd& state, const Eigen::VectorXd& force,
                      double speed) const override;
  double clearance() const override { return journal_.clearance; }
  std::string ownDofName(int k) const override { return "pad" + std::to_string(k + 1) + "_tilt"; }

 private:
  /// One pad at the last call: where the journal is in its axes (/ c_p) and the force (N,
  /// along e_k and t_k).
  struct PadState {
    double rho = 0, s = 0, forceE = 0, forceT = 0;
  };
  FilmLoad solve(const Eigen::VectorXd& state, const Eigen::VectorXd& rate, double speed) const;
  Eigen::Vector2d unit(double angle) const;

  PlainJournal journal_;
  TiltingPads pads_;
  ReynoldsGrid grid_;
  double loadAngle_ = 0;
  double padClearance_ = 0;     ///< c_p
  std::vector<double> pivots_;  ///< global angles of the pivots
  mutable std::mutex mutex_;    ///< guards the pads' films and the memo
  mutable std::vector<PadFilm> films_;
  mutable std::vector<PadState> states_;
  mutable Eigen::VectorXd lastState_, lastRate_;
  mutable double lastSpeed_ = -1;
  mutable FilmLoad lastLoad_;
};

}  // namespace beamrotor

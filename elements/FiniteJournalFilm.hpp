// The finite-length plain journal bearing's film as a nonlinear force: the same Reynolds film,
// grid and cavitation condition as the linearised coefficients of
// elements/FiniteJournalBearing.hpp, at any journal position and velocity.
//
// Film (elements/ReynoldsFilm.hpp): a journal at e = eps c (cos psi, sin psi) from the
// bearing's centre (global y, z; angles from +y towards +z, the sense of rotation) leaves the
// film H = 1 + eps cos(theta) with theta measured from the largest gap, global angle
// alpha = psi + pi, where the film starts (P = 0 there, Raimondi and Boyd's line, as for the
// coefficients). In that film's axes (axis 1 towards the largest gap, axis 2 a quarter turn
// on, R = R(alpha) turning them into global ones) the journal's velocity is
// w = R^T v / (c Omega), the squeeze term of Reynolds' equation; the active-set solve gives the
// force f(eps, w) (dimensionless), and F = mu Omega R_j^3 L / c^2 R f.
//
// Derivatives, exact to the discrete film: one factorisation of the film on its pressurised
// nodes serves the force and the three perturbation right-hand sides (solveArcFilm):
//  - velocity: D = -df/dw, C = mu R_j^3 L / c^3 R D R^T;
//  - displacement along the line of centres (axis 1, the largest gap stays at theta = 0): the
//    perturbed film equation, column 1 of K;
//  - across it (axis 2, eta / c): the journal turns by -eta / eps and the whole film with it
//    (the film starts at the largest gap wherever that is), carrying its frame and so the
//    velocity's components in it: -df/deta = (J f + D J w) / eps, J the quarter turn. At rest
//    (w = 0) this is the coefficients' (-f2, f1) / eps.
// At rest at the film's equilibrium these are finiteJournalPoint's coefficients to round-off.
//
// At eps -> 0 the film's start line (the largest gap) is undefined: a journal within 1e-9 c of
// the centre is taken 1e-9 c out along its last direction (+y's opposite at first); with a
// velocity the force there is direction dependent (the start line turns with the journal),
// as in the theory the coefficients come from. At Omega = 0 the pure squeeze film is taken at a
// spin of 1e-9 rad/s (P scales with the wedge and squeeze terms together, so the scaling by
// Omega stays finite; the wedge's share is then below round-off of any squeeze).
//
// Cost: each call starts the active set from the last call's cavity (a Newton step moves the
// journal little: one or two factorisations of the banded film), and a call at the state of
// the last one returns its answer (docs/runup.md measures it).
#pragma once

#include <mutex>
#include <vector>

#include "elements/PlainJournalFilm.hpp"
#include "elements/ReynoldsFilm.hpp"

namespace beamrotor {

class FiniteJournalFilm : public PlainJournalFilm {
 public:
  /// The journal's geometry and oil (its `load` is not used: the load comes with each call),
  /// and the film's grid (the one the bearing's coefficients are solved on).
  FiniteJournalFilm(const PlainJournal& journal, const ReynoldsGrid& grid);
  FilmForce at(const Eigen::Vector2d& position, const Eigen::Vector2d& velocity,
               double speed) const override;

 private:
  /// finiteJournalPoint's eccentricity and attitude.
  Resting resting(double W, double speed) const override;

  /// The answer at one state, and the film's pressurised nodes there.
  struct Memo {
    Eigen::Vector2d position{0, 0}, velocity{0, 0};
    double speed = -1;
    FilmForce film;
    std::vector<char> cavity;
    Eigen::Vector2d direction{-1, 0};  ///< towards the journal (from the bearing's centre)
  };
  FilmForce solve(const Eigen::Vector2d& position, const Eigen::Vector2d& velocity,
                  double speed, Memo& memo) const;

  ReynoldsGrid grid_;
  mutable std::mutex mutex_;  ///< guards memo_ (one film may serve several threads)
  mutable Memo memo_;
};

}  // namespace beamrotor

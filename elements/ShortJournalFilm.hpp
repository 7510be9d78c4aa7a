// The short (Ocvirk) bearing's film as a nonlinear force: the same theory as the linearised
// coefficients of elements/PlainJournalBearing.hpp, at any journal position and velocity.
//
// Film (Hamrock, Fundamentals of Fluid Film Lubrication, 1994, ch. 13; Childs, Turbomachinery
// Rotordynamics, 1993, ch. 4): a journal at (y, z) from the bearing's centre, moving at
// (y', z'), leaves the gap h = c - y cos(theta) - z sin(theta) at angle theta (from +y towards
// +z, the sense of rotation). Without the circumferential pressure flow Reynolds' equation
// integrates along the axis: p = g(theta) (z_a^2 - L^2 / 4) / (2 h^3) (z_a along the axis,
// 0 at the middle) with g = 6 mu Omega dh/dtheta + 12 mu dh/dt; with X = y / c, Y = z / c,
//   g / (mu c) = G = (6 Omega X - 12 Y') sin(theta) - (6 Omega Y + 12 X') cos(theta).
// G is a sinusoid: the film carries pressure where G < 0, exactly half the circumference
// (Gumbel's condition, the "pi film", turned by the journal's motion), and the force on the
// journal is
//   F = mu R L^3 / (12 c^2) int_{G < 0} G / H^3 (cos, sin)(theta) dtheta,  H = h / c.
// At rest in the bearing this is the classical short-bearing load and attitude (the linear
// coefficients are its derivatives there). Since G = 0 at both ends of the film, the
// derivatives of F are the integrals of the integrand's derivatives over the same half: exact.
// The half-turn integrals are taken by 64-point Gauss-Legendre quadrature: the integrand is
// analytic, with poles where H = 0, at a distance acosh(1 / eps) from the real axis, so the
// error falls like rho^-128 with rho = 1.5 at eps = 0.99 (below 1e-20: round-off).
#pragma once

#include "elements/PlainJournalFilm.hpp"

namespace beamrotor {

class ShortJournalFilm : public PlainJournalFilm {
 public:
  /// The journal's geometry and oil (its `load` is not used: the load comes with each call).
  explicit ShortJournalFilm(const PlainJournal& journal);
  FilmForce at(const Eigen::Vector2d& position, const Eigen::Vector2d& velocity,
               double speed) const override;

 private:
  /// Ocvirk's equilibrium: eccentricity from the Sommerfeld number (eccentricityRatio), the
  /// attitude angle of that eccentricity.
  Resting resting(double W, double speed) const override;
};

}  // namespace beamrotor

// A plain cylindrical journal bearing of any length: Reynolds' equation solved by finite
// volumes over the film, the load it carries, and its eight coefficients by perturbation.
//
// Film: elements/ReynoldsFilm.hpp over the whole circumference, theta measured from the line of
// largest film, H = 1 + eps cos(theta), the film starting there (P = 0 at theta = 0, as in
// Raimondi and Boyd 1958), the Reynolds cavitation condition.
//
// Load: F = mu Omega R^3 L / c^2 * Fbar, Fbar = -int_0^2pi int_0^1 P (cos, sin) dzeta dtheta;
// the Sommerfeld number S = (mu N L D / W)(R/c)^2 = 1 / (pi |Fbar|). The eccentricity ratio
// that carries the load is the root of |Fbar(eps)| = 1 / (pi S) (regula falsi, Illinois).
//
// Coefficients: the film equation linearised about the equilibrium for small velocities of
// the journal and a small displacement along the line of centres, on the pressurised nodes of
// the equilibrium (the perturbed pressure is 0 on the cavity's boundary, where the base
// pressure and its gradient vanish, and on the line of largest film, which these do not move).
// A displacement across the line of centres turns the film with the journal (the film starts
// at the largest gap, wherever that is): its stiffness follows from the force itself. Their
// forces are exact derivatives of the discrete force; rotated into global axes.
//
// Discretisation: `circumferential` cells around the circumference (docs/finite-journal-bearing.md).
#pragma once

#include "elements/Bearing.hpp"
#include "elements/PlainJournalBearing.hpp"
#include "elements/ReynoldsFilm.hpp"

namespace beamrotor {

/// Solves the full circle's film (elements/ReynoldsFilm.hpp: a = eps, b = 0; axis 1 towards
/// the largest film, theta = 0, axis 2 a quarter turn later) at eps (0 < eps < 1) for
/// L/D = lengthOverDiameter (> 0), the journal displaced and moving by `motion` (none by default: the steady film, whose derivatives with
/// respect to the motion are the coefficients).
/// Throws std::runtime_error when the active set does not settle (never seen).
FilmSolution solveFilm(double eps, double lengthOverDiameter, const ReynoldsGrid& grid,
                       const JournalMotion& motion = {});

/// The journal's operating point: eccentricity ratio, attitude angle (rad, between the load
/// line and the line of centres, in the sense of rotation as in attitudeAngle) and the eight
/// coefficients in global axes (as shortBearingCoefficients).
struct JournalOperatingPoint {
  double eccentricity = 0;
  double attitude = 0;
  BearingCoefficients coefficients;
};

/// The largest eccentricity ratio the finite model solves for: thinner films than 1 % of the
/// clearance are beyond any real surface finish (as for the short bearing, JournalTable.cpp).
inline constexpr double kFiniteMaxEccentricity = 0.99;

/// The finite bearing's operating point at spin speed Omega (rad/s, > 0), on `grid`. Throws
/// std::invalid_argument when the load needs an eccentricity above kFiniteMaxEccentricity.
JournalOperatingPoint finiteJournalPoint(const PlainJournal& bearing, double speed,
                                         const ReynoldsGrid& grid);

}  // namespace beamrotor

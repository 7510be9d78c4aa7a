// A plain cylindrical journal bearing of any length: Reynolds' equation solved by finite
// volumes over the film, the load it carries, and its eight coefficients by perturbation.
//
// Film (Hamrock, Fundamentals of Fluid Film Lubrication, 1994, ch. 12 and 13; Lund, "Review of
// the concept of dynamic coefficients for fluid film journal bearings", J. Tribol. 109, 1987):
// theta is measured from the line of largest film, in the sense of rotation, zeta = 2 z / L
// along the axis. With H = h / c = 1 + eps cos(theta) and P = p c^2 / (mu Omega R^2),
//   d/dtheta (H^3 dP/dtheta) + (D/L)^2 d/dzeta (H^3 dP/dzeta) = 6 dH/dtheta + 12 dH/dtau,
// tau = Omega t. The film is symmetric about the mid-plane (dP/dzeta = 0 at zeta = 0); P = 0
// at the bearing's ends (zeta = +-1) and on the line of largest film (theta = 0: the film
// starts there, as in Raimondi and Boyd 1958).
//
// Cavitation: the Reynolds (Swift-Stieber) condition, P >= 0 with the film equation where
// P > 0 and P = 0 (and, in the limit, dP/dn = 0) on the boundary of the cavity. Discretely a
// linear complementarity problem, solved by a primal-dual active set: the film equation on
// the pressurised nodes (a sparse symmetric positive definite system, Eigen's LDL'), P = 0 on
// the others, repeated until the set no longer changes (finite for an M-matrix).
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
// Discretisation: cells of equal size, `circumferential` around the circumference and `axial`
// on the half length; second order in both (docs/finite-journal-bearing.md measures it).
#pragma once

#include "elements/Bearing.hpp"
#include "elements/PlainJournalBearing.hpp"

namespace beamrotor {

/// Film grid: cells around the circumference, cells on the half length (mid-plane to end).
struct ReynoldsGrid {
  int circumferential = 72;
  int axial = 8;
};

/// The film at eccentricity ratio eps, dimensionless, in the frame of the line of centres:
/// axis 1 towards the largest film (theta = 0), axis 2 a quarter turn later.
struct FilmSolution {
  double force[2] = {0, 0};  ///< Fbar (see the header)
  double stiffness[2][2]{};  ///< -dFbar_i / d(x_j / c)
  double damping[2][2]{};    ///< -dFbar_i / d(x_j' / (c Omega))
  int activeSetIterations = 0;
};

/// A journal displaced from eccentricity eps by `displacement` (/ c) and moving at `velocity`
/// (/ (c Omega)), in the frame of FilmSolution; the film still starts at theta = 0 (for a
/// displacement across the line of centres that is not where the gap is largest: the
/// stiffness column of such a displacement is the turned film's, see the header).
struct JournalMotion {
  double displacement[2] = {0, 0};
  double velocity[2] = {0, 0};
};

/// Solves the film at eps (0 < eps < 1) for L/D = lengthOverDiameter (> 0), the journal
/// displaced and moving by `motion` (none by default: the steady film, whose derivatives with
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

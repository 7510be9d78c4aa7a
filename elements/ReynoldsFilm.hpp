// An oil film over an arc of a journal: Reynolds' equation solved by finite volumes, with the
// Reynolds (Swift-Stieber) cavitation condition, its force on the journal and the linearised
// stiffness and damping of that force. The plain journal bearing (elements/FiniteJournalBearing)
// is the film over the whole circumference; a tilting pad (elements/TiltingPadBearing) is the
// film over its own arc.
//
// Film (Hamrock, Fundamentals of Fluid Film Lubrication, 1994, ch. 12 and 13; Lund, "Review of
// the concept of dynamic coefficients for fluid film journal bearings", J. Tribol. 109, 1987):
// theta is measured in the sense of rotation (the journal's surface moves towards +theta),
// zeta = 2 z / L along the axis. The film is H = h / c = 1 + a cos(theta) + b sin(theta) on
// start <= theta <= start + span (any circular arc about any centre has this shape to first
// order in c / R). With P = p c^2 / (mu Omega R^2),
//   d/dtheta (H^3 dP/dtheta) + (D/L)^2 d/dzeta (H^3 dP/dzeta) = 6 dH/dtheta + 12 dH/dtau,
// tau = Omega t. The film is symmetric about the mid-plane (dP/dzeta = 0 at zeta = 0); P = 0
// at the bearing's ends (zeta = +-1) and at both edges of the arc (the full circle's edges are
// one line, where its film starts, as in Raimondi and Boyd 1958).
//
// Cavitation: P >= 0 with the film equation where P > 0 and P = 0 (and, in the limit,
// dP/dn = 0) on the boundary of the cavity. Discretely a linear complementarity problem, solved
// by a primal-dual active set: the film equation on the pressurised nodes (a sparse symmetric
// positive definite system, Eigen's LDL'), P = 0 on the others, repeated until the set no
// longer changes (finite for an M-matrix).
//
// Force: F = mu Omega R^3 L / c^2 * Fbar, Fbar = -int int P (cos, sin)(theta) dzeta dtheta
// (zeta from 0 to 1: both halves of the length).
//
// Coefficients: the film equation linearised about the solution for small displacements and
// velocities of the journal along (cos, sin)(0) and (cos, sin)(pi/2) (dH = -(cos, sin) per unit
// of x / c), on the pressurised nodes (the perturbed pressure is 0 on the cavity's boundary,
// where the base pressure and its gradient vanish, and on the arc's edges, which do not move).
// Their forces are exact derivatives of the discrete force.
//
// Discretisation: cells of equal size, `circumferential` over the arc and `axial` on the half
// length; second order in both (docs/finite-journal-bearing.md measures it).
#pragma once

#include <numbers>
#include <vector>

namespace beamrotor {

/// Film grid: cells over the arc (the circumference, or one pad), cells on the half length.
struct ReynoldsGrid {
  int circumferential = 72;
  int axial = 8;
};

/// The film's arc and shape: H = 1 + a cos(theta) + b sin(theta) on [start, start + span].
struct FilmArc {
  double start = 0;
  double span = 2 * std::numbers::pi;
  double a = 0, b = 0;
};

/// The film's force and its derivatives, dimensionless (see the header), in the axes of theta:
/// axis 1 along theta = 0, axis 2 along theta = pi/2.
struct FilmSolution {
  double force[2] = {0, 0};  ///< Fbar
  double stiffness[2][2]{};  ///< -dFbar_i / d(x_j / c)
  double damping[2][2]{};    ///< -dFbar_i / d(x_j' / (c Omega))
  int activeSetIterations = 0;
};

/// A journal displaced by `displacement` (/ c) and moving at `velocity` (/ (c Omega)) from the
/// film's shape: the film is then H - d1 cos - d2 sin, squeezed at -(v1 cos + v2 sin).
struct JournalMotion {
  double displacement[2] = {0, 0};
  double velocity[2] = {0, 0};
};

/// Solves the film over `arc` for L/D = lengthOverDiameter (> 0; infinity gives the long
/// film, each axial station on its own). The film must be positive over the arc. With
/// `withCoefficients` the stiffness and damping are filled too. `cavity`, when given and of the
/// grid's size, is the first guess of the pressurised nodes (a neighbouring film's) and returns
/// this film's. Throws std::invalid_argument for a bad arc, grid or film, std::runtime_error
/// when the active set does not settle (never seen).
FilmSolution solveArcFilm(const FilmArc& arc, double lengthOverDiameter, const ReynoldsGrid& grid,
                          const JournalMotion& motion, bool withCoefficients,
                          std::vector<char>* cavity = nullptr);

}  // namespace beamrotor

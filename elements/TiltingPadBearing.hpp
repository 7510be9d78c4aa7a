// A tilting-pad journal bearing from its pads' geometry: the journal's equilibrium, each pad
// tilted until its film's force passes through its pivot, and the pads' dynamic coefficients
// condensed onto the journal at a whirl frequency (the synchronous set at the spin speed).
//
// Geometry (Lund, "Spring and damping coefficients for the tilting-pad journal bearing", ASLE
// Trans. 7, 1964; Nicholas, "Tilting pad bearing design", Proc. 23rd Turbomachinery Symp.,
// 1994): n pads of arc beta each, the pivot a fraction alpha (the offset) of the arc from the
// pad's leading edge (0.5: centred); bearing clearance c_b (from the bearing's centre to a
// pivot's pad surface, less R), pad clearance c_p (the pad's bore radius less R) and preload
// m = 1 - c_b / c_p. In the bearing's axes (x_b, y_b), the load along -x_b, angles theta from
// +x_b in the sense of rotation: the pivots sit at theta_k = pi + 2 pi k / n (load on a pad)
// or pi + pi / n + 2 pi k / n (load between two pads).
//
// Film of pad k (elements/ReynoldsFilm.hpp, lengths over c_p): with phi = theta - theta_k, a
// journal at u (/ c_p) and the pad's centre of curvature moved by tau across the pivot line
// (a tilt tau c_p / R about the pivot, the pivot on the pad's surface),
//   H = 1 - m cos(phi) - u . (cos, sin)(theta) + tau sin(phi)
//     = 1 - (m + rho) cos(phi) - s sin(phi),   rho = u . e_k, s = u . t_k - tau,
// e_k = (cos, sin)(theta_k) towards the pivot, t_k a quarter turn on, phi on
// [-alpha beta, (1 - alpha) beta]. The film depends on the journal's motion relative to the
// pad's centre of curvature only, so its force f_k(u - tau t_k) and the pad's generalised force
// -f_k . t_k (on tau) share one 2 x 2 impedance Z_k = K_k + i nu C_k (pad axes e_k, t_k;
// nu = whirl / spin).
//
// Equilibrium: each pad tilts until f_k . t_k = 0 (s such that the film's force passes through
// the pivot; a root between the two films that close at the pad's edges), so f_k depends on rho
// only; the journal moves (Newton on u, its Jacobian the bearing's static stiffness) until
// sum f_k carries the load W: mu Omega R^3 L / c_p^2 * sum fbar_k = W along +x_b.
//
// Coefficients: a massless pad follows the journal, t_k . Z_k (u - tau t_k) = 0, so
// tau = (t_k . Z_k u) / (t_k . Z_k t_k), and the pad's impedance on the journal is condensed to
//   Z_k' = Z_k - Z_k t_k t_k^T Z_k / (t_k^T Z_k t_k)   (Lund 1964; Allaire, Parsell and
// Barrett, "A pad perturbation method for the dynamic coefficients of tilting-pad journal
// bearings", Wear 72, 1981); the bearing's is sum_k Z_k', K = Re, C = Im / nu (dimensional:
// K mu Omega R^3 L / c_p^3, C mu R^3 L / c_p^3). At nu = 1 the synchronous set; at nu = 0 the
// static stiffness, which is the Jacobian of the load against the journal's displacement.
#pragma once

#include <complex>
#include <vector>

#include "elements/Bearing.hpp"
#include "elements/PlainJournalBearing.hpp"
#include "elements/ReynoldsFilm.hpp"

namespace beamrotor {

/// The pads of a tilting-pad bearing (the journal, oil and load are a PlainJournal's, its
/// clearance the bearing clearance c_b).
struct TiltingPads {
  int count = 4;             ///< pads
  double arc = 0;            ///< each pad's arc beta (rad), count * arc < 2 pi
  double pivotOffset = 0.5;  ///< pivot from the leading edge over the arc, 0 < alpha < 1
  double preload = 0;        ///< m = 1 - c_b / c_p, 0 <= m < 1
  bool loadOnPad = false;    ///< the load line through a pivot, or between two pads
};

/// One pad at the journal's equilibrium: dimensionless, pad axes (e_k, t_k).
struct PadFilmState {
  double pivot = 0;          ///< theta_k (rad)
  double force = 0;          ///< the film's force on the journal along e_k (N; < 0: pushes)
  double tilt = 0;           ///< the pad's tilt about its pivot (rad), tau c_p / R
  double minimumFilm = 0;    ///< the thinnest film on the pad over c_b
  double stiffness[2][2]{};  ///< K_k, over mu Omega R^3 L / c_p^3
  double damping[2][2]{};    ///< C_k, over mu R^3 L / c_p^3
};

struct TiltingPadPoint {
  double eccentricity = 0;  ///< |u| c_p / c_b
  double attitude = 0;      ///< rad from the load line to the journal's centre, sense of rotation
  double speed = 0;         ///< rad/s
  double radius = 0;        ///< the journal's radius R (m)
  std::vector<PadFilmState> pads;
  double stiffnessScale = 0, dampingScale = 0;  ///< mu Omega R^3 L / c_p^3, mu R^3 L / c_p^3
  BearingCoefficients synchronous;              ///< condensed at whirl = spin, bearing's axes
};

/// One pad alone, in its own axes (e_k, t_k), the journal at rho (/ c_p) towards its pivot:
/// the tilt s (see the header) that turns the film's force through the pivot, and that film
/// with its coefficients; not `loaded` for a pad the journal has left.
struct PadEquilibrium {
  bool loaded = false;
  double s = 0;
  FilmSolution film;
};
PadEquilibrium padEquilibrium(const TiltingPads& pads, double lengthOverDiameter,
                              const ReynoldsGrid& grid, double rho);

/// The bearing's equilibrium and coefficients at spin speed Omega (rad/s, > 0), each pad's film
/// on `grid` (cells over one pad's arc). Throws std::invalid_argument for bad geometry, a pad
/// whose film cannot turn its force through the pivot, or a load that needs a film thinner
/// than 1 % of c_b. `near`, when given (the same bearing at a nearby speed), is where Newton
/// starts from: the same equilibrium to Newton's tolerance (1e-11 of the load) in fewer steps.
TiltingPadPoint tiltingPadPoint(const PlainJournal& bearing, const TiltingPads& pads, double speed,
                                const ReynoldsGrid& grid, const TiltingPadPoint* near = nullptr);

/// The coefficients condensed at whirl = whirlRatio * Omega (whirlRatio > 0; 1: synchronous),
/// in the bearing's axes as Bearing.hpp names them (x_b -> y).
BearingCoefficients tiltingPadCoefficients(const TiltingPadPoint& point, double whirlRatio);

/// The coefficients a motion e^{lambda t} (lambda in 1/s, Im lambda >= 0) sees, the pads
/// condensed exactly at lambda (Z_k' with Z_k = K_k + (lambda / Omega) C_k): real K and C with
/// K + lambda C = Z'(lambda), C = Im Z' / Im lambda, K = Re Z' - Re lambda C, bearing's axes
/// (x_b -> y). At lambda = i nu Omega the set tiltingPadCoefficients gives at nu.
BearingCoefficients tiltingPadCoefficientsAt(const TiltingPadPoint& point,
                                              std::complex<double> lambda);

/// The static stiffness (whirl -> 0): the Jacobian of the pads' load against the journal's
/// displacement, each pad at its equilibrium tilt. Damping terms are left 0.
BearingCoefficients tiltingPadStaticStiffness(const TiltingPadPoint& point);

}  // namespace beamrotor

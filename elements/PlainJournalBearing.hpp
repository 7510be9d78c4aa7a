// A plain cylindrical journal bearing from its geometry and oil: the steady eccentricity and
// the eight linearised stiffness and damping coefficients of the oil film, by the short
// (Ocvirk) bearing theory, against spin speed.
//
// Theory (Friswell, Penny, Garvey, Lees, Dynamics of Rotating Machines, Cambridge 2010,
// sec. 5.5.1; Hamrock, Fundamentals of Fluid Film Lubrication, 1994, ch. 13): for L/D small
// the circumferential pressure flow is negligible, Reynolds' equation integrates along the
// axis in closed form, and the film carries pressure only where it converges (Gumbel
// condition: half the film, 0 <= theta <= pi from the thinnest gap backwards). A journal at
// eccentricity ratio eps = e / c carries the load W when the modified Sommerfeld number
//   S_s = mu Omega D L^3 / (8 W c^2) = (1 - eps^2)^2 / (eps sqrt(16 eps^2 + pi^2 (1 - eps^2)))
// (S_s = pi S (L/D)^2 with S = (mu N / P)(R / c)^2 the classical Sommerfeld number, N in rev/s,
// P = W / (L D)), with its centre displaced from the load line by the attitude angle
// phi, tan phi = pi sqrt(1 - eps^2) / (4 eps), in the direction of rotation.
//
// Frame: the static load pushes the journal towards -y (global; the bearing's -x_b), the
// shaft spins about +x (from +y towards +z). The force of the film on the journal is, to
// first order about that position, -K (uy, uz) - C (uy', uz') with (h0 = (pi^2 (1 - eps^2)
// + 16 eps^2)^(-3/2), s = sqrt(1 - eps^2))
//   kyy = W/c 4 h0 (pi^2 (1 + 2 eps^2) + 32 eps^2 (1 + eps^2) / s^2)
//   kzz = W/c 4 h0 (pi^2 (2 - eps^2) + 16 eps^2)
//   kyz = W/c h0 pi (pi^2 s^2 (1 + 2 eps^2) + 32 eps^2 (1 + eps^2)) / (eps s)
//   kzy = -W/c h0 pi (pi^2 s^4 - 16 eps^4) / (eps s)
//   cyy = W/(c Omega) 2 pi h0 (pi^2 s^4 + 48 eps^2) / (eps s)
//   czz = W/(c Omega) 2 pi h0 s (pi^2 (1 + 2 eps^2) - 16 eps^2) / eps
//   cyz = czy = W/(c Omega) 8 h0 (pi^2 (1 + 2 eps^2) - 16 eps^2)
// (Friswell's a_vv, a_uu, -a_vu, -a_uv, b_vv, b_uu, -b_uv with v along the load, u a quarter
// turn behind it in the sense of rotation.)
#pragma once

#include <Eigen/Dense>

#include "elements/Bearing.hpp"

namespace beamrotor {

/// Geometry, oil and static load of a plain cylindrical journal bearing (SI).
struct PlainJournal {
  double diameter = 0;   ///< journal diameter D (m)
  double length = 0;     ///< axial length L (m)
  double clearance = 0;  ///< radial clearance c (m)
  double viscosity = 0;  ///< dynamic viscosity mu of the oil (Pa s)
  double load = 0;       ///< static load W carried (N), acting towards -y

  /// mu Omega D L^3 / (8 W c^2) at spin speed Omega (rad/s).
  double sommerfeld(double speed) const;
};

/// The short-bearing load capacity as a modified Sommerfeld number at eccentricity ratio eps
/// (0 < eps < 1): decreasing from infinity at eps = 0 to 0 at eps = 1.
double shortBearingSommerfeld(double eps);

/// The eccentricity ratio at which the short bearing carries its load at spin speed Omega
/// (rad/s, > 0): the root of shortBearingSommerfeld(eps) = sommerfeld(Omega), to round-off.
double eccentricityRatio(const PlainJournal& bearing, double speed);

/// Attitude angle phi (rad) between the load line and the line of centres at eps.
double attitudeAngle(double eps);

/// The eight coefficients at spin speed Omega (rad/s, > 0), global axes (see the header).
BearingCoefficients shortBearingCoefficients(const PlainJournal& bearing, double speed);

/// The film's torque resisting the journal's spin (N m) with the journal at `position` (m,
/// global y, z from the bearing's centre) and the film pushing on it with `force` (N), at spin
/// speed Omega (rad/s): the Couette shear over the whole gap, 2 pi mu Omega R^3 L / (c sqrt(1 -
/// eps^2)), plus the pressure flow's shear, which for any film pressure vanishing at the film's
/// edges integrates by parts to half the moment x cross F about the bearing's centre (the film
/// is massless: the journal's and the bearing's torques differ by x cross F, each the Couette
/// torque plus or minus that half). Any film theory: its force comes with the call.
double journalDragTorque(const PlainJournal& bearing, const Eigen::Vector2d& position,
                         const Eigen::Vector2d& force, double speed);

}  // namespace beamrotor

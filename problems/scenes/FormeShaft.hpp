// Spring-mounted forme shaft: the plate cylinder of a sheet-fed offset press on two bearing
// springs (problems/scenes/README.md section 2). Two parts:
//   1. the paper's rigid two-dof closed form (bounce z of the centre of mass, rotation phi in
//      the vertical plane), with the decoupled case b = 0 resolved, and its rotor extension;
//   2. the finite-element model of the same shaft (journals, barrel, drive gear, springs) and
//      its rigid-body properties, to check the closed form and to measure how much the shaft's
//      flexibility lowers the frequencies.
//
// Frame: the shaft along x from the operator-side end; y is the paper's vertical z (planar
// models bend in the x-y plane: uy = z, rz = phi, positive phi lifting B, the drive side).
// SI units.
//
//   m z''       + (C1 + C2) z       + (C2 l2 - C1 l1) phi      = 0
//   m rho^2 phi'' + (C2 l2 - C1 l1) z + (C1 l1^2 + C2 l2^2) phi = 0
//   a = (C1 + C2)/m, b = (C2 l2 - C1 l1)/m, d = (C1 l1^2 + C2 l2^2)/m,
//   k^4 - (d/rho^2 + a) k^2 + (a d - b^2)/rho^2 = 0,   n_i = z/phi = b / (k_i^2 - a).
#pragma once

#include <array>
#include <string_view>

#include "fem/model/Model.hpp"
#include "meshes/LineBuilder.hpp"

namespace beamrotor {

// ---- 1. The rigid two-dof model -------------------------------------------------------------

/// The rigid shaft on springs.
struct FormeShaftRigid {
  double m = 0;           ///< mass (kg)
  double J = 0;           ///< moment of inertia about the centre of mass, bending plane (kg m^2)
  double C1 = 0, C2 = 0;  ///< spring stiffnesses at A and B (N/m)
  double l1 = 0, l2 = 0;  ///< distances from the centre of mass to A (-x side), B (+x side) (m)

  double rho2() const { return J / m; }                           ///< rho^2 (m^2)
  double a() const { return (C1 + C2) / m; }                      ///< 1/s^2
  double b() const { return (C2 * l2 - C1 * l1) / m; }            ///< m/s^2
  double d() const { return (C1 * l1 * l1 + C2 * l2 * l2) / m; }  ///< m^2/s^2
};

enum class FormeModeKind {
  coupled,  ///< b != 0: bounce and rotation together
  bounce,   ///< b = 0: pure translation (phi = 0), k^2 = a
  rocking,  ///< b = 0: pure rotation about the centre of mass (z = 0), k^2 = d / rho^2
};
std::string_view formeModeKindName(FormeModeKind k);

/// One free-vibration mode z = z sin(k t), phi = phi sin(k t).
struct FormeShaftMode {
  double k = 0;  ///< natural frequency (rad/s)
  FormeModeKind kind = FormeModeKind::coupled;
  /// Amplitudes (m, rad) scaled so that z^2 + rho^2 phi^2 = 1 (kinetic energy of a unit
  /// translation), sign chosen so the larger of z and rho phi is positive.
  double z = 0, phi = 0;
  /// Amplitude ratio n = z / phi (m/rad) = b / (k^2 - a); +infinity for pure bounce
  /// (phi = 0, the b -> 0 limit of the bounce-like root), 0 for pure rocking.
  double n = 0;
  /// Dynamic spring loads at these amplitudes: C1 (z - l1 phi) at A, C2 (z + l2 phi) at B (N).
  double FA = 0, FB = 0;
  double inertiaForce = 0;   ///< -m k^2 z (N); balances FA + FB
  double inertiaMoment = 0;  ///< -J k^2 phi (N m); balances l2 FB - l1 FA
};

/// |b| at or below this fraction of (C1 l1 + C2 l2) / m counts as b = 0 (round-off of C2 l2
/// - C1 l1 when the springs were chosen to balance): the modes are then labelled bounce and
/// rocking. The amplitudes are computed without cancellation either way.
inline constexpr double kFormeDecoupled = 1e-12;

/// The two modes, k1 <= k2.
std::array<FormeShaftMode, 2> formeShaftModes(const FormeShaftRigid& s);

/// The paper's name of mode `ascending` (0-based) of formeShaftModes: the paper calls the "+"
/// root of the biquadratic (the higher frequency) k1 and the "-" root k2, so our mode 1 is its
/// k2 and our mode 2 its k1. Returns "k2 ('-' root)" or "k1 ('+' root)".
std::string_view paperModeName(int ascending);

/// Our 0-based index of the paper's mode k<paper> (paper = 1 or 2): 1 for k1, 0 for k2.
inline int ascendingIndexOfPaperMode(int paper) { return paper == 1 ? 1 : 0; }

/// Rotor extension (b = 0, isotropic springs, spin Omega in rad/s): the conical whirl
/// ( +-Jp Omega + sqrt(Jp^2 Omega^2 + 4 J k_phi) ) / (2 J), k_phi = C1 l1^2 + C2 l2^2,
/// sense +1 forward (rises with speed), -1 backward. The bounce stays at sqrt(a).
double formeShaftWhirl(const FormeShaftRigid& s, double Jp, double speed, int sense);

// ---- 2. The finite-element model ------------------------------------------------------------

/// A plate cylinder of a B1-format (720 x 1020 mm sheet) sheet-fed offset press, the class of
/// e.g. a Heidelberg Speedmaster 102: barrel about 0.3 m across and 1.05 m long, in steel.
/// The values are rounded engineering estimates of such a cylinder, not a maker's drawing:
/// a hollow barrel (0.30 m outer, 0.18 m bore: ~370 kg), 0.10 m journals with the bearings
/// 0.08 m from the barrel faces, the drive-side journal long enough to carry the drive gear
/// (pitch diameter ~ the barrel's, as the cylinders gear 1:1; 0.06 m face; lightened by a web
/// to ~25 kg), and rolling bearings in eccentric bushings and side frames of ~2e8 N/m.
/// The gear puts the centre of mass ~6 cm towards the drive side of mid-bearing span.
struct FormeShaftDesign {
  double operatorJournal = 0.16;            ///< length of the operator-side journal (m)
  double barrelLength = 1.05;               ///< m
  double driveJournal = 0.30;               ///< length of the drive-side journal (m)
  double journalDiameter = 0.10;            ///< m
  double barrelDiameter = 0.30;             ///< m
  double barrelBore = 0.18;                 ///< m (0 for a solid barrel)
  double bearingInset = 0.08;               ///< bearing centre from the barrel face, both sides (m)
  double gearInset = 0.22;                  ///< gear centre from the drive-side barrel face (m)
  double gearMass = 25;                     ///< kg
  double gearJp = 0.28;                     ///< polar moment (kg m^2), ~ m R^2 / 2 with R = 0.15 m
  double gearJd = 0.15;                     ///< transverse moment (kg m^2), ~ m (R^2/4 + w^2/12)
  double C1 = 2e8, C2 = 2e8;                ///< spring (bearing) stiffness at A and B (N/m)
  double E = 2.1e11, nu = 0.3, rho = 7850;  ///< steel
  double elementSize = 0.05;                ///< largest beam element (m)
};

/// The FE model and where things are.
struct FormeShaftModel {
  Model model;
  Line line;
  int nodeA = -1, nodeB = -1, nodeGear = -1;
  double xA = 0, xB = 0;  ///< bearing stations (m)
};

/// Builds the shaft with Timoshenko beams (consistent mass with rotary inertia), the gear as a
/// PointInertia and the bearings: planar dofs (ux, uy, rz) get grounded Springs on uy and a
/// thrust support holding ux at A; lateral dofs (uy, uz, ry, rz) get isotropic Bearings.
FormeShaftModel buildFormeShaft(const FormeShaftDesign& design, DofSet dofs);

/// Rigid-body properties from the FE matrices: the mass matrix projected on a rigid
/// translation (uy = 1) and a rigid rotation about z (uy = x, rz = 1), and for lateral models
/// the gyroscopic matrix between rigid tilts about y and z (Jp).
struct RigidBodyProperties {
  double m = 0;   ///< kg
  double xG = 0;  ///< centre of mass (m)
  double J = 0;   ///< about the centre of mass in the x-y plane (kg m^2)
  double Jp = 0;  ///< polar, about x (kg m^2); 0 for planar models
};
RigidBodyProperties rigidBodyProperties(const Model& model);

/// The two-dof model of an FE shaft: its rigid-body properties and the springs at xA, xB.
FormeShaftRigid rigidModel(const RigidBodyProperties& body, double xA, double xB, double C1,
                           double C2);

}  // namespace beamrotor

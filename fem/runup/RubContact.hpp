// Rub: a shaft station touching a stator across a radial clearance, with Coulomb friction, as a
// nonlinear force for the run-up (fem/runup/RunUp.hpp), with the exact derivatives its Newton
// iterations need.
//
// The station's centre at x = (y, z) from the stator's centre (the node's displacement), moving
// at v. Past the clearance, delta = |x| - c > 0, the stator pushes back along the outward normal
// n = x / |x| with the penalty N = k delta + d delta' (N >= 0: a contact that separates faster
// than k delta / d pulls nothing). The shaft's surface at the contact point slides over the
// stator at v_s = t . v + R Omega (t = (-n_z, n_y), the sense of rotation: the centre's whirl
// velocity plus the surface's spin velocity); Coulomb's friction mu N opposes it. The sign of
// v_s is regularised, s(v_s) = v_s / sqrt(v_s^2 + v_e^2) (within 1 % of Coulomb's once
// |v_s| > 7 v_e, smooth and odd, so Newton keeps its quadratic rate through stick): the force
// on the shaft is
//   F = -N n - mu N s(v_s) t,
// and the friction brakes the spin with the torque T = mu N s(v_s) R. The contact dissipates
// mu N s v_s (>= 0) by friction and d delta'^2 in its normal damper; k delta^2 / 2 is stored.
#pragma once

#include <Eigen/Dense>
#include <cmath>
#include <string>

namespace beamrotor {

/// A rub station: where, across what clearance, how stiff and how rough the contact is.
struct RubContact {
  std::string name;
  int node = -1;            ///< the shaft's node (uy, uz free)
  double clearance = 0;     ///< c, radial (m, > 0)
  double stiffness = 0;     ///< k, the contact's penalty stiffness (N/m, > 0)
  double damping = 0;       ///< d, normal damping in contact (N s/m, >= 0)
  double friction = 0;      ///< mu, Coulomb's coefficient (>= 0)
  double radius = 0;        ///< R, the shaft's radius at the contact (m, > 0)
  double slipVelocity = 0;  ///< v_e, the regularisation's velocity (m/s, > 0)
};

/// The contact's force on the shaft and its derivatives, global (y, z), and its torque on the
/// spin.
struct RubForce {
  Eigen::Vector2d force = Eigen::Vector2d::Zero();      ///< N
  Eigen::Matrix2d stiffness = Eigen::Matrix2d::Zero();  ///< -dF/dx (N/m)
  Eigen::Matrix2d damping = Eigen::Matrix2d::Zero();    ///< -dF/dv (N s/m)
  double normal = 0;                                    ///< N (N, >= 0)
  double penetration = 0;                               ///< delta = |x| - c (m; < 0: clear)
  double slip = 0;                                      ///< v_s (m/s)
  double torque = 0;       ///< mu N s R, braking the spin (N m)
  double torqueSlope = 0;  ///< dT/dOmega (N m s)
  /// Power dissipated: by friction mu N s v_s and by the normal damper d delta'^2 (W)
  double frictionPower = 0, dampingPower = 0;
  bool touching() const { return normal > 0; }
};

/// The rub force at centre x (m, from the stator's centre), velocity v (m/s) and spin speed
/// `speed` (rad/s).
inline RubForce rubForce(const RubContact& r, const Eigen::Vector2d& x, const Eigen::Vector2d& v,
                         double speed) {
  RubForce out;
  const double rho = x.norm();
  out.penetration = rho - r.clearance;
  if (!(out.penetration > 0)) return out;
  const Eigen::Vector2d n = x / rho, t(-n[1], n[0]);
  const Eigen::Matrix2d turn{{0, -1}, {1, 0}};  // t = turn n
  const Eigen::Matrix2d P = (Eigen::Matrix2d::Identity() - n * n.transpose()) / rho;  // dn/dx
  const double rate = n.dot(v);  // delta'
  const double N = r.stiffness * out.penetration + r.damping * rate;
  if (!(N > 0)) return out;
  const double vs = t.dot(v) + r.radius * speed;
  const double root = std::sqrt(vs * vs + r.slipVelocity * r.slipVelocity);
  const double s = vs / root;
  const double ds = r.slipVelocity * r.slipVelocity / (root * root * root);  // ds/dv_s
  const double g = r.friction * N * s;                                        // friction, signed
  // Row gradients: of N, of v_s and of g, in x and v.
  const Eigen::RowVector2d dNdx = r.stiffness * n.transpose() + r.damping * v.transpose() * P;
  const Eigen::RowVector2d dNdv = r.damping * n.transpose();
  const Eigen::RowVector2d dVdx = v.transpose() * turn * P, dVdv = t.transpose();
  const Eigen::RowVector2d dgdx = r.friction * (s * dNdx + N * ds * dVdx);
  const Eigen::RowVector2d dgdv = r.friction * (s * dNdv + N * ds * dVdv);
  out.force = -N * n - g * t;
  out.stiffness = n * dNdx + N * P + t * dgdx + g * turn * P;
  out.damping = n * dNdv + t * dgdv;
  out.normal = N;
  out.slip = vs;
  out.torque = g * r.radius;
  out.torqueSlope = r.friction * N * ds * r.radius * r.radius;
  out.frictionPower = g * vs;
  out.dampingPower = r.damping * rate * rate;
  return out;
}

}  // namespace beamrotor

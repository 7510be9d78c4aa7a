// Independent references for the stepped pump rod of problems/scenes/README.md section 1,
// shared by its tests: an initial-parameter (transfer-matrix) solution marched numerically
// piece by piece (the decks use the same method in closed form, by Cramer's rule), and the
// piston's largest tilt from the width of the tilted core.
#pragma once

#include <Eigen/Dense>
#include <cmath>
#include <numbers>
#include <utility>

namespace beamrotor::test {

/// The rod's data (the paper's, SI units) at stroke position eta.
struct PumpRod {
  double a = 0.575, d = 1.130, D1 = 0.120, D2 = 0.070, E = 200e9;
  double eta = 0.4;
  double psi() const { return a + 0.715 - eta; }
  double l() const { return a + d; }
};

/// Reactions on the rod (+y forces, counter-clockwise moments) and the piston-end rotation.
struct PumpRodResponse {
  double leftForce, leftMoment, middleForce, rightForce, rightMoment, rightRotation;
};

/// Initial-parameter method: state (w, theta, M, V) with w' = theta, theta' = M/EI, M' = V
/// (M sagging-positive, V the sum of upward forces left of the section), carried across
/// prismatic pieces exactly; the middle support adds its force to V. Unknowns M(0), V(0),
/// the middle force; conditions w(psi) = 0 and, at the right end, w = 0 with theta = 0
/// (clamped) or M = 0 (hinged). Left end: w = -w0, theta = 0.
inline PumpRodResponse pumpRodInitialParameters(const PumpRod& r, double w0, bool rightClamped) {
  const double EI1 = r.E * std::numbers::pi * std::pow(r.D1, 4) / 64;
  const double EI2 = r.E * std::numbers::pi * std::pow(r.D2, 4) / 64;
  const double psi = r.psi(), l = r.l();
  auto carry = [](Eigen::Vector4d s, double h, double EI) {
    return Eigen::Vector4d(s[0] + s[1] * h + s[2] * h * h / (2 * EI) + s[3] * h * h * h / (6 * EI),
                           s[1] + s[2] * h / EI + s[3] * h * h / (2 * EI), s[2] + s[3] * h, s[3]);
  };
  // Returns (w(psi-), state at the right end) for given unknowns.
  auto march = [&](double w, double M0, double V0, double P3) {
    Eigen::Vector4d s(-w, 0, M0, V0);
    s = carry(s, r.a, EI1);
    s = carry(s, psi - r.a, EI2);
    const double wMiddle = s[0];
    s[3] += P3;
    s = carry(s, l - psi, EI2);
    return std::make_pair(wMiddle, s);
  };
  auto conditions = [&](double w, const Eigen::Vector3d& x) {
    const auto [wm, s] = march(w, x[0], x[1], x[2]);
    return Eigen::Vector3d(wm, s[0], rightClamped ? s[1] : s[2]);
  };
  // The conditions are linear in (w0, unknowns): one column per unknown, then solve.
  Eigen::Matrix3d A;
  for (int j = 0; j < 3; ++j) A.col(j) = conditions(0, Eigen::Vector3d::Unit(j));
  const Eigen::Vector3d x = A.lu().solve(-conditions(w0, Eigen::Vector3d::Zero()));
  const auto [wm, s] = march(w0, x[0], x[1], x[2]);
  // Left force V(0), left moment -M(0), middle force P3, right force -V(l), right moment M(l).
  return {x[1], -x[0], x[2], -s[3], s[2], s[1]};
}

/// Largest tilt of the piston's core (diameter Dp, length lp) in the liner bore Dc: tilted by
/// theta the core spans Dp cos(theta) + lp sin(theta) across the bore, which grows with theta
/// up to the diagonal; the stop is where it equals Dc. Solved by bisection to round-off (the
/// decks use the equivalent arccos form of problems/scenes/README.md section 1).
inline double pistonTiltLimit(double Dp, double lp, double Dc) {
  double lo = 0, hi = std::atan2(lp, Dp);  // the span peaks (at the diagonal) at atan(lp/Dp)
  for (int i = 0; i < 200 && hi - lo > 1e-18; ++i) {
    const double mid = (lo + hi) / 2;
    (Dp * std::cos(mid) + lp * std::sin(mid) < Dc ? lo : hi) = mid;
  }
  return (lo + hi) / 2;
}

}  // namespace beamrotor::test

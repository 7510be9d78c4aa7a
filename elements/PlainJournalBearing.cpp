#include "elements/PlainJournalBearing.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <stdexcept>

namespace beamrotor {

namespace {

constexpr double kPi = std::numbers::pi;

}  // namespace

double PlainJournal::sommerfeld(double speed) const {
  return viscosity * speed * diameter * length * length * length /
         (8 * load * clearance * clearance);
}

double shortBearingSommerfeld(double eps) {
  const double s2 = 1 - eps * eps;
  return s2 * s2 / (eps * std::sqrt(16 * eps * eps + kPi * kPi * s2));
}

double eccentricityRatio(const PlainJournal& bearing, double speed) {
  const double target = bearing.sommerfeld(speed);
  if (!(target > 0) || !std::isfinite(target))
    throw std::invalid_argument("a plain journal bearing needs a positive speed, load and geometry");
  // shortBearingSommerfeld falls monotonically over (0, 1): bisection to the last bit.
  double lo = 0, hi = 1;
  while (true) {
    const double mid = 0.5 * (lo + hi);
    if (mid <= lo || mid >= hi) return mid;
    (shortBearingSommerfeld(mid) > target ? lo : hi) = mid;
  }
}

double attitudeAngle(double eps) {
  return std::atan2(kPi * std::sqrt(1 - eps * eps), 4 * eps);
}

BearingCoefficients shortBearingCoefficients(const PlainJournal& bearing, double speed) {
  const double e = eccentricityRatio(bearing, speed);
  const double e2 = e * e, pi2 = kPi * kPi;
  const double s2 = 1 - e2, s = std::sqrt(s2);
  const double h0 = std::pow(pi2 * s2 + 16 * e2, -1.5);
  const double k = bearing.load / bearing.clearance, c = k / speed;
  BearingCoefficients out;
  out.kyy = k * 4 * h0 * (pi2 * (1 + 2 * e2) + 32 * e2 * (1 + e2) / s2);
  out.kzz = k * 4 * h0 * (pi2 * (2 - e2) + 16 * e2);
  out.kyz = k * h0 * kPi * (pi2 * s2 * (1 + 2 * e2) + 32 * e2 * (1 + e2)) / (e * s);
  out.kzy = -k * h0 * kPi * (pi2 * s2 * s2 - 16 * e2 * e2) / (e * s);
  out.cyy = c * 2 * kPi * h0 * (pi2 * s2 * s2 + 48 * e2) / (e * s);
  out.czz = c * 2 * kPi * h0 * s * (pi2 * (1 + 2 * e2) - 16 * e2) / e;
  out.cyz = out.czy = c * 8 * h0 * (pi2 * (1 + 2 * e2) - 16 * e2);
  return out;
}

double journalDragTorque(const PlainJournal& bearing, const Eigen::Vector2d& position,
                         const Eigen::Vector2d& force, double speed) {
  const double c = bearing.clearance, R = bearing.diameter / 2;
  const double eps = std::min(position.norm() / c, 1 - 1e-12);
  const double couette = 2 * std::numbers::pi * bearing.viscosity * speed * R * R * R *
                         bearing.length / (c * std::sqrt(1 - eps * eps));
  return couette + (position[0] * force[1] - position[1] * force[0]) / 2;
}

}  // namespace beamrotor

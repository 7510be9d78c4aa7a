#include "elements/PadFilm.hpp"

#include <algorithm>
#include <cmath>
#include <functional>
#include <stdexcept>
#include <string>

#include "fem/rotor/SpeedRoot.hpp"

namespace beamrotor {

FilmSolution PadFilm::solve(double rho, double s, bool withCoefficients) {
  return solveAt(rho, s, JournalMotion{}, withCoefficients);
}

FilmSolution PadFilm::solveMoving(double rho, double s, const double rates[2]) {
  JournalMotion motion;
  motion.velocity[0] = rates[0];
  motion.velocity[1] = rates[1];
  return solveAt(rho, s, motion, true);
}

FilmSolution PadFilm::solveAt(double rho, double s, const JournalMotion& motion,
                              bool withCoefficients) {
  const double r0 = motion.velocity[0], r1 = motion.velocity[1];
  if (withCoefficients && last_ && last_->rho == rho && last_->s == s && last_->rate0 == r0 &&
      last_->rate1 == r1)
    return last_->film;
  FilmSolution f = solveArcFilm(shape(rho, s), ld_, grid_, motion, withCoefficients, &cavity_);
  if (withCoefficients) last_ = Solved{rho, s, r0, r1, f};
  return f;
}

double PadFilm::thinnest(double rho, double s) const {
  const FilmArc a = shape(rho, s);
  double h = 1e300;
  for (int i = 0; i <= grid_.circumferential; ++i) {
    const double t = a.start + a.span * i / grid_.circumferential;
    h = std::min(h, 1 + a.a * std::cos(t) + a.b * std::sin(t));
  }
  return h;
}

std::optional<double> PadFilm::equilibriumTilt(double rho) {
  const double a = preload_ + rho;
  if (!(1 - a > 0)) throw std::invalid_argument("the journal reaches a pad's pivot");
  double low = -1e300, high = 1e300;
  for (int i = 0; i <= grid_.circumferential; ++i) {
    const double phi = arc_ * (double(i) / grid_.circumferential - offset_);
    if (std::abs(phi) < 1e-14) continue;
    const double bound = (1 - a * std::cos(phi)) / std::sin(phi);
    if (phi > 0) high = std::min(high, bound);
    else low = std::max(low, bound);
  }
  auto sOf = [&](double t) { return low + t * (high - low); };
  auto moment = [&](double t) { return solve(rho, sOf(t), false).force[1]; };
  if (lastRoot_)
    if (const std::optional<double> s = newtonTilt(rho, *lastRoot_, low, high))
      return lastRoot_ = s;
  // Near the last root first (the Newton steps move the journal little): a bracket of
  // +-0.02 around it, when the moment changes sign there.
  if (lastRoot_) {
    const double t = (*lastRoot_ - low) / (high - low);
    const double a1 = std::max(t - 0.02, 1e-4), b1 = std::min(t + 0.02, 1 - 1e-4);
    if (a1 < b1) {
      const double ma = moment(a1), mb = moment(b1);
      if (ma > 0 && mb < 0) return lastRoot_ = sOf(speedRoot(moment, a1, ma, b1, mb, 1e-13).speed);
    }
  }
  // Step away from the closing trailing edge (through s = 0) until the moment changes sign.
  std::vector<double> steps{1 - 1e-4, 1 - 1e-3, 0.99, 0.97};
  for (double t = 0.95; t > 0.01; t -= 0.025) steps.push_back(t);
  if (const double t0 = -low / (high - low); t0 > 0 && t0 < 1) steps.push_back(t0);
  std::sort(steps.begin(), steps.end(), std::greater<>());
  double tHigh = steps[0], mHigh = moment(tHigh);
  for (std::size_t k = 1; k < steps.size() && mHigh < 0; ++k) {
    const double t = steps[k], m = moment(t);
    if (m > 0) return lastRoot_ = sOf(speedRoot(moment, t, m, tHigh, mHigh, 1e-13).speed);
    tHigh = t;
    mHigh = m;
  }
  // A pad the journal has left carries nothing.
  if (a <= 0) return std::nullopt;
  throw std::invalid_argument(
      "a pad's film cannot turn its force through the pivot (pivot offset " +
      std::to_string(offset_) + ")");
}

/// Newton on the pad's moment f . t from s, its slope the film's own stiffness
/// (d(f . t)/ds = -K_tt, the tilt moving the film as the journal does along t): one film a
/// step, against some eight for the bracketed root. The tilt whose step falls below 1e-13 of
/// the bracket (the bracketed root's tolerance); none when a step leaves (low, high), the
/// slope is not negative, or ten steps do not settle (the caller then brackets).
std::optional<double> PadFilm::newtonTilt(double rho, double s, double low, double high) {
  constexpr double kTiltTolerance = 1e-13;
  constexpr int kNewtonSteps = 10;
  for (int step = 0; step < kNewtonSteps; ++step) {
    if (!(s > low && s < high)) return std::nullopt;
    const FilmSolution f = solve(rho, s, true);
    const double slope = -f.stiffness[1][1];
    if (!(slope < 0)) return std::nullopt;
    const double ds = -f.force[1] / slope;
    if (std::abs(ds) <= kTiltTolerance * (high - low)) return s;
    s += ds;
  }
  return std::nullopt;
}

}  // namespace beamrotor

#include "fem/model/LineElement.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>

namespace beamrotor {

SectionForces SectionForceSeries::at(double s) const {
  const auto value = [&](double SectionForces::*f) {
    return c[0].*f + s * (c[1].*f + s * (c[2].*f + s * c[3].*f));
  };
  return {value(&SectionForces::N), value(&SectionForces::Vy), value(&SectionForces::Vz),
          value(&SectionForces::T), value(&SectionForces::My), value(&SectionForces::Mz)};
}

namespace {

/// The largest of d . p over the fibre's points p (its support function in direction d).
double support(const StressFibre& fibre, double dy, double dz) {
  const double atCentre = dy * fibre.y + dz * fibre.z;
  if (fibre.radius == 0) return atCentre;
  // Over the whole circle the largest lies in direction d itself; on an arc only when d's
  // angle lies within the arc, otherwise at the nearer end (the support is then linear).
  const double twoPi = 2 * std::numbers::pi;
  const double angle = std::atan2(dz, dy);
  const double past = std::fmod(std::fmod(angle - fibre.from, twoPi) + twoPi, twoPi);
  if (fibre.sweep >= twoPi || past <= fibre.sweep || (dy == 0 && dz == 0))
    return atCentre + fibre.radius * std::hypot(dy, dz);
  double best = -std::numeric_limits<double>::infinity();
  for (double end : {fibre.from, fibre.from + fibre.sweep})
    best = std::max(best, atCentre + fibre.radius * (dy * std::cos(end) + dz * std::sin(end)));
  return best;
}

}  // namespace

FibreStressField fibreStressField(const Section& s, const SectionForces& f) {
  return {f.N / s.A, -f.Mz / s.Iz, f.My / s.Iy};
}

double fibreNormalStress(const StressFibre& fibre, const FibreStressField& field) {
  const auto [c, a, b] = field;
  return std::max(c + support(fibre, a, b), -c + support(fibre, -a, -b));
}

double maxNormalStress(const Section& s, const SectionForces& f) {
  if (s.fibres.empty()) return std::numeric_limits<double>::quiet_NaN();
  const FibreStressField field = fibreStressField(s, f);
  double best = 0;
  for (const StressFibre& fibre : s.fibres) {
    const double v = fibreNormalStress(fibre, field);
    if (std::isnan(v)) return v;
    best = std::max(best, v);
  }
  return best;
}

}  // namespace beamrotor

#include "fem/model/SignedStress.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>

#include "fem/model/ShearStress.hpp"

namespace beamrotor {

double fibreSupport(const StressFibre& fibre, double dy, double dz) {
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

YFibreStresses yFibreStresses(const Section& s, const SectionForces& f) {
  const double nan = std::numeric_limits<double>::quiet_NaN();
  if (s.fibres.empty()) return {nan, nan};
  double top = -std::numeric_limits<double>::infinity(), bottom = -top;
  for (const StressFibre& fibre : s.fibres) {
    top = std::max(top, fibreSupport(fibre, 1, 0));
    bottom = std::min(bottom, -fibreSupport(fibre, -1, 0));
  }
  // sigma(y) = N / A - Mz y / Iz on the line z = 0 (fibreStressField's c and a).
  const FibreStressField field = fibreStressField(s, f);
  return {field.c + field.a * top, field.c + field.a * bottom};
}

double signedShearY(const Section& s, const SectionForces& f) {
  return std::copysign(maxShearStress(s, SectionForces{.Vy = f.Vy}), f.Vy);
}

double signedShearZ(const Section& s, const SectionForces& f) {
  return std::copysign(maxShearStress(s, SectionForces{.Vz = f.Vz}), f.Vz);
}

}  // namespace beamrotor

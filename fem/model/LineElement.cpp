#include "fem/model/LineElement.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>

#include "fem/model/SignedStress.hpp"

namespace beamrotor {

SectionForces SectionForceSeries::at(double s) const {
  const auto value = [&](double SectionForces::*f) {
    return c[0].*f + s * (c[1].*f + s * (c[2].*f + s * c[3].*f));
  };
  return {value(&SectionForces::N), value(&SectionForces::Vy), value(&SectionForces::Vz),
          value(&SectionForces::T), value(&SectionForces::My), value(&SectionForces::Mz)};
}

FibreStressField fibreStressField(const Section& s, const SectionForces& f) {
  return {f.N / s.A, -f.Mz / s.Iz, f.My / s.Iy};
}

double fibreNormalStress(const StressFibre& fibre, const FibreStressField& field) {
  const auto [c, a, b] = field;
  return std::max(c + fibreSupport(fibre, a, b), -c + fibreSupport(fibre, -a, -b));
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

#include "fem/model/LineElement.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>
#include <stdexcept>
#include <string>

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

Eigen::Vector3d thermalStrain(const Section& s, double dT, double dTy, double dTz) {
  // The section's depth along a direction (a, b): its largest plus its smallest coordinate
  // there over the fibres, which lie on the convex hull of the outline.
  const auto depth = [&](double a, double b, const char* axis) {
    if (s.fibres.empty())
      throw std::invalid_argument("a temperature gradient across local " + std::string(axis) +
                                  " needs the depth of section '" + s.name +
                                  "' (a general section without its depth has none)");
    double high = -std::numeric_limits<double>::infinity(), low = high;
    for (const StressFibre& f : s.fibres) {
      high = std::max(high, fibreSupport(f, a, b));
      low = std::max(low, fibreSupport(f, -a, -b));
    }
    return high + low;
  };
  const double alpha = s.material.alpha;
  return {alpha * dT, dTz == 0 ? 0 : alpha * dTz / depth(0, 1, "z"),
          dTy == 0 ? 0 : -alpha * dTy / depth(1, 0, "y")};
}

}  // namespace beamrotor

#include "fem/model/LineElement.hpp"

#include <cmath>

namespace beamrotor {

SectionForces SectionForceSeries::at(double s) const {
  const auto value = [&](double SectionForces::*f) {
    return c[0].*f + s * (c[1].*f + s * c[2].*f);
  };
  return {value(&SectionForces::N), value(&SectionForces::Vy), value(&SectionForces::Vz),
          value(&SectionForces::T), value(&SectionForces::My), value(&SectionForces::Mz)};
}

double maxNormalStress(const Section& s, const SectionForces& f) {
  const double axial = std::abs(f.N) / s.A;
  if (s.shape == Section::Shape::circle || s.shape == Section::Shape::tube)
    return axial + std::hypot(f.My, f.Mz) * s.outerY / s.Iz;
  return axial + std::abs(f.Mz) * s.outerY / s.Iz + std::abs(f.My) * s.outerZ / s.Iy;
}

}  // namespace beamrotor

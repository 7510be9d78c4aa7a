#include "fem/model/ShearStress.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>

namespace beamrotor {

double shearStressFactor(const Section& s) {
  switch (s.shape) {
    case Section::Shape::circle: {
      const double nu = s.material.nu;
      return (3 + 2 * nu) / (2 * (1 + nu));
    }
    case Section::Shape::tube: {
      // Outer radius from the outer fibre, inner from the area A = pi (R^2 - r^2).
      const double R = s.outerY;
      const double r2 = std::max(0.0, R * R - s.A / std::numbers::pi), r = std::sqrt(r2);
      return 4 * (R * R + R * r + r2) / (3 * (R * R + r2));
    }
    case Section::Shape::rectangle:
      return 1.5;
    case Section::Shape::general:
      break;
    case Section::Shape::iSection:
    case Section::Shape::channel:
    case Section::Shape::angle:
    case Section::Shape::hollowRectangle:
      return std::max(s.shearPeakY, s.shearPeakZ);
  }
  return 1.0;
}

double maxShearStress(const Section& s, const SectionForces& f) {
  if (s.shearPeakY > 0 || s.shearPeakZ > 0)
    return (s.shearPeakY * std::abs(f.Vy) + s.shearPeakZ * std::abs(f.Vz)) / s.A;
  return shearStressFactor(s) * std::hypot(f.Vy, f.Vz) / s.A;
}

}  // namespace beamrotor

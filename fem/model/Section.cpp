#include "fem/model/Section.hpp"

#include <cmath>
#include <numbers>
#include <stdexcept>

namespace beamrotor {

namespace {
constexpr double kPi = std::numbers::pi;

void require(bool ok, const std::string& what) {
  if (!ok) throw std::invalid_argument(what);
}
}  // namespace

Material Material::fromEnu(std::string name, double E, double nu, double rho) {
  require(std::isfinite(E) && E > 0, "Young's modulus E must be positive");
  require(std::isfinite(nu) && nu > -1 && nu < 0.5, "Poisson's ratio nu must lie in (-1, 0.5)");
  require(std::isfinite(rho) && rho >= 0, "density rho must be non-negative");
  return Material{std::move(name), E, nu, E / (2 * (1 + nu)), rho};
}

Section Section::circle(std::string name, const Material& m, double D) {
  require(std::isfinite(D) && D > 0, "diameter must be positive");
  const double R = D / 2, I = kPi * std::pow(D, 4) / 64;
  // Cowper (1966), solid circle.
  const double kappa = 6 * (1 + m.nu) / (7 + 6 * m.nu);
  Section s{std::move(name), Shape::circle, m,     kPi * R * R, I, I,
            2 * I,           kappa,         kappa, R,           R, D, {}, 0, 0};
  s.fibres = {StressFibre{0, 0, R, 0, 2 * kPi}};
  return s;
}

Section Section::tube(std::string name, const Material& m, double D, double t) {
  require(std::isfinite(D) && D > 0, "outer diameter must be positive");
  require(std::isfinite(t) && t > 0 && 2 * t <= D, "wall thickness must lie in (0, D/2]");
  const double d = D - 2 * t;
  const double I = kPi * (std::pow(D, 4) - std::pow(d, 4)) / 64;
  // Cowper (1966), hollow circle with inner/outer radius ratio c.
  const double c = d / D, c2 = c * c, nu = m.nu;
  const double kappa = 6 * (1 + nu) * (1 + c2) * (1 + c2) /
                       ((7 + 6 * nu) * (1 + c2) * (1 + c2) + (20 + 12 * nu) * c2);
  Section s{std::move(name), Shape::tube, m, kPi * (D * D - d * d) / 4, I, I, 2 * I, kappa, kappa,
            D / 2,           D / 2,       D,   {}, 0, 0};
  s.fibres = {StressFibre{0, 0, D / 2, 0, 2 * kPi}};
  return s;
}

Section Section::rectangle(std::string name, const Material& m, double b, double h) {
  require(std::isfinite(b) && b > 0 && std::isfinite(h) && h > 0,
          "rectangle width and height must be positive");
  // Saint-Venant torsion constant, series approximation (Roark): a >= c the long/short sides.
  const double a = std::max(b, h), c = std::min(b, h);
  const double J = a * c * c * c * (1.0 / 3 - 0.21 * c / a * (1 - std::pow(c / a, 4) / 12));
  // Cowper (1966), rectangle.
  const double kappa = 10 * (1 + m.nu) / (12 + 11 * m.nu);
  Section s{std::move(name),
                 Shape::rectangle,
                 m,
                 b * h,
                 h * b * b * b / 12,
                 b * h * h * h / 12,
                 J,
                 kappa,
                 kappa,
                 h / 2,
                 b / 2,
                 std::max(b, h),
                 {},
                 0,
                 0};
  s.fibres = cornerFibres(h / 2, b / 2);
  return s;
}

Section Section::general(std::string name, const Material& m, double A, double Iy, double Iz,
                         double J, double kappaY, double kappaZ, double depth) {
  require(std::isfinite(A) && A > 0, "area A must be positive");
  require(std::isfinite(Iy) && Iy > 0 && std::isfinite(Iz) && Iz > 0,
          "second moments Iy, Iz must be positive");
  require(std::isfinite(J) && J >= 0, "torsion constant J must be non-negative");
  require(kappaY >= 0 && kappaZ >= 0, "shear coefficients must be non-negative");
  Section s{std::move(name), Shape::general, m, A, Iy, Iz, J, kappaY, kappaZ, 0, 0, depth, {}, 0, 0};
  if (depth > 0) s.setExtent(depth, depth);
  return s;
}

void Section::setExtent(double alongY, double alongZ) {
  require(std::isfinite(alongY) && alongY >= 0 && std::isfinite(alongZ) && alongZ >= 0,
          "section extents must be non-negative");
  outerY = alongY / 2;
  outerZ = alongZ / 2;
  depth = std::max(alongY, alongZ);
  fibres = cornerFibres(outerY, outerZ);
}

std::vector<StressFibre> cornerFibres(double cy, double cz) {
  if (cz == 0) return {StressFibre{cy, 0}, StressFibre{-cy, 0}};
  if (cy == 0) return {StressFibre{0, cz}, StressFibre{0, -cz}};
  return {StressFibre{cy, cz}, StressFibre{-cy, cz}, StressFibre{-cy, -cz}, StressFibre{cy, -cz}};
}

}  // namespace beamrotor

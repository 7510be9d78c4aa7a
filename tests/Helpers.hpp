// Shared test helpers: small models built the way decks build them, and relative errors.
#pragma once

#include <cmath>
#include <memory>
#include <numbers>

#include "elements/Beam.hpp"
#include "fem/model/Model.hpp"
#include "meshes/LineBuilder.hpp"

namespace beamrotor::test {

inline constexpr double kPi = std::numbers::pi;

inline double relError(double computed, double reference) {
  return std::abs(computed - reference) / std::abs(reference);
}

/// Root of a continuous f on [a, b] with a sign change, by bisection to round-off.
template <class F>
inline double bisectRoot(F f, double a, double b) {
  double fa = f(a);
  for (int i = 0; i < 200 && b - a > 1e-15 * std::abs(b); ++i) {
    const double m = (a + b) / 2, fm = f(m);
    if ((fm < 0) == (fa < 0)) {
      a = m;
      fa = fm;
    } else {
      b = m;
    }
  }
  return (a + b) / 2;
}

/// Discrete-to-exact frequency ratio of a simply supported uniform Euler-Bernoulli beam meshed
/// with equal cubic Hermite elements of length h and consistent mass, for the mode of wave
/// number k = n pi / L (the discrete dispersion relation). The nodal values w_j = sin(k x_j),
/// theta_j = c cos(k x_j) satisfy every interior row of K - w^2 M (and the simply supported ends)
/// when, per unit EI / h^3 and rho A h / 420, with C = cos(k h), S = sin(k h) and c scaled by h,
///   K2 = [24 (1 - C), -12 S; -12 S, 8 + 4 C],   M2 = [312 + 108 C, 26 S; 26 S, 8 - 6 C],
/// and the lower root mu of det(K2 - mu M2) = 0 gives w^2 = 420 mu EI / (rho A h^4); the exact
/// w^2 is EI k^4 / (rho A). Asymptotically 1 + (k h)^4 / 1440.
inline double hermiteSimplySupportedFrequencyRatio(double kh) {
  const double C = std::cos(kh), S = std::sin(kh), oneMinusC = 2 * std::pow(std::sin(kh / 2), 2);
  const double k11 = 24 * oneMinusC, k12 = -12 * S, k22 = 8 + 4 * C;
  const double m11 = 312 + 108 * C, m12 = 26 * S, m22 = 8 - 6 * C;
  // det = a mu^2 + b mu + c; the lower root in the cancellation-free form 2 c / (-b + sqrt(.)).
  const double a = m11 * m22 - m12 * m12, b = -(k11 * m22 + k22 * m11 - 2 * k12 * m12);
  const double c = 48 * oneMinusC * oneMinusC;  // k11 k22 - k12^2, without its cancellation
  const double mu = 2 * c / (-b + std::sqrt(b * b - 4 * a * c));
  return std::sqrt(420 * mu) / (kh * kh);
}

inline std::shared_ptr<const Section> steelCircle(double D) {
  return std::make_shared<Section>(
      Section::circle("d", Material::fromEnu("steel", 200e9, 0.3, 7850), D));
}

inline std::shared_ptr<const Section> steelRectangle(double b, double h) {
  return std::make_shared<Section>(
      Section::rectangle("r", Material::fromEnu("steel", 210e9, 0.3, 7850), b, h));
}

/// A uniform straight beam along x with `n` elements; points "start" and "end".
inline Line uniformBeam(Model& model, double L, std::shared_ptr<const Section> s, int n,
                        DofSet dofs = DofSet::planar(), BeamOptions options = {}) {
  LineSpec spec;
  spec.dofs = dofs;
  spec.segments.push_back({L, std::move(s), n, 0, options});
  spec.points = {{"start", 0}, {"end", L}};
  return buildLine(model, spec);
}

/// Fixes every carried dof of a node.
inline void clamp(Model& model, const std::string& name, int node, DofSet dofs) {
  Support s{name, node, {}};
  for (Dof d : kAllDofs)
    if (dofs.contains(d)) s.dofs.push_back({d, 0});
  model.addSupport(s);
}

}  // namespace beamrotor::test

#include "fem/model/ThinWalledShear.hpp"

#include <algorithm>
#include <cmath>

namespace beamrotor {

namespace {
/// 3-point Gauss-Legendre on [0, 1]: exact for Q^2, a polynomial of degree 4 along a wall.
constexpr double kNodes[3] = {0.5 - 0.3872983346207417, 0.5, 0.5 + 0.3872983346207417};
constexpr double kWeights[3] = {5.0 / 18, 8.0 / 18, 5.0 / 18};
}  // namespace

ShearFlow shearFlow(const std::vector<Wall>& chain, double Q0, double dy, double dz) {
  ShearFlow flow;
  double Q = Q0;
  for (const Wall& w : chain) {
    const double L = std::hypot(w.y1 - w.y0, w.z1 - w.z0);
    const double c0 = dy * w.y0 + dz * w.z0, c1 = dy * w.y1 + dz * w.z1;
    // Q(u) = Q + t L (c0 u + (c1 - c0) u^2 / 2) for u = s / L in [0, 1].
    const auto at = [&](double u) { return Q + w.t * L * (c0 * u + (c1 - c0) * u * u / 2); };
    for (int g = 0; g < 3; ++g) {
      const double q = at(kNodes[g]);
      flow.energy += kWeights[g] * L * q * q / w.t;
    }
    // |Q| is largest at an end or where dQ/ds = t c vanishes.
    std::vector<double> places{0, 1};
    if (c0 != c1 && c0 * c1 < 0) places.push_back(c0 / (c0 - c1));
    for (double u : places) flow.peak = std::max(flow.peak, std::abs(at(u)) / w.t);
    Q = at(1);
  }
  flow.end = Q;
  return flow;
}

ThinWalledShear thinWalledShear(double energy, double peak, double I, double A) {
  return {I * I / (A * energy), A * peak / I};
}

double midlineSecondMoment(const std::vector<Wall>& walls, double dy, double dz) {
  double I = 0;
  for (const Wall& w : walls) {
    const double L = std::hypot(w.y1 - w.y0, w.z1 - w.z0);
    const double c0 = dy * w.y0 + dz * w.z0, c1 = dy * w.y1 + dz * w.z1;
    I += w.t * L * (c0 * c0 + c0 * c1 + c1 * c1) / 3;  // int of a linear c squared
  }
  return I;
}

}  // namespace beamrotor

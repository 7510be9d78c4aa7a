// Gauss-Legendre rules on [-1, 1]: N points integrate polynomials up to degree 2N - 1 exactly,
// and analytic functions with an error that falls geometrically with N.
#pragma once

#include <array>
#include <cmath>
#include <numbers>

namespace beamrotor {

/// Nodes and weights of the N-point rule (Newton on the Legendre polynomial P_N from the
/// asymptotic guesses of its roots).
template <int N>
struct GaussLegendre {
  static constexpr int n = N;
  std::array<double, N> x{}, w{};
  GaussLegendre() {
    for (int i = 0; i < N; ++i) {
      double t = std::cos(std::numbers::pi * (i + 0.75) / (N + 0.5)), dp = 1;
      for (int iteration = 0; iteration < 100; ++iteration) {
        double p0 = 1, p1 = t;
        for (int k = 2; k <= N; ++k) {
          const double p2 = ((2 * k - 1) * t * p1 - (k - 1) * p0) / k;
          p0 = p1;
          p1 = p2;
        }
        dp = N * (t * p1 - p0) / (t * t - 1);
        const double step = p1 / dp;
        t -= step;
        if (std::abs(step) < 1e-16) break;
      }
      x[i] = t;
      w[i] = 2 / ((1 - t * t) * dp * dp);
    }
  }
};

}  // namespace beamrotor

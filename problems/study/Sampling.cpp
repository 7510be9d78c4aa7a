#include "problems/study/Sampling.hpp"

#include <cmath>
#include <numbers>

namespace beamrotor {

double openUniform(std::mt19937_64& engine) {
  const std::uint64_t k = engine() >> 11;  // 53 bits
  return (double(k) + 0.5) * 0x1.0p-53;
}

std::uint64_t uniformIndex(std::mt19937_64& engine, std::uint64_t n) {
  // The largest multiple of n that fits: draws at or above it would favour small indices.
  const std::uint64_t limit = std::uint64_t(-1) - std::uint64_t(-1) % n;
  for (;;) {
    const std::uint64_t x = engine();
    if (x < limit) return x % n;
  }
}

double normalCdf(double x) { return 0.5 * std::erfc(-x / std::numbers::sqrt2); }

double normalQuantile(double p) {
  if (!(p > 0 && p < 1)) return std::nan("");
  // Work in the lower tail, where Phi(x) is computed without cancellation; mirror back.
  const bool upper = p > 0.5;
  const double q = upper ? 1 - p : p;
  const double t = std::sqrt(-2 * std::log(q));
  double x = -(t - (2.515517 + 0.802853 * t + 0.010328 * t * t) /
                       (1 + 1.432788 * t + 0.189269 * t * t + 0.001308 * t * t * t));
  for (int step = 0; step < 3; ++step) {
    const double density = std::exp(-0.5 * x * x) / std::sqrt(2 * std::numbers::pi);
    const double residual = normalCdf(x) - q;
    // Halley: Phi'' = -x Phi', so x -= r / (Phi' (1 + x r / (2 Phi'))).
    const double newton = residual / density;
    x -= newton / (1 + 0.5 * x * newton);
  }
  return upper ? -x : x;
}

}  // namespace beamrotor

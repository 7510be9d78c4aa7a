#include "problems/converge/ConvergenceRates.hpp"

#include <cmath>

namespace beamrotor {

std::optional<double> observedOrder(double coarseError, double fineError) {
  if (!(coarseError > 0) || !(fineError > 0) || !std::isfinite(coarseError) ||
      !std::isfinite(fineError))
    return std::nullopt;
  return std::log2(coarseError / fineError);
}

Extrapolation richardson(double q0, double q1, double q2) {
  const double d1 = q1 - q0, d2 = q2 - q1;
  if (d1 == 0 || d2 == 0 || (d1 > 0) != (d2 > 0) || std::abs(d2) >= std::abs(d1))
    return {q2, std::nullopt};
  const double p = std::log2(d1 / d2);
  return {q2 + d2 / (std::pow(2.0, p) - 1), p};
}

}  // namespace beamrotor

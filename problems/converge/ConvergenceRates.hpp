// Observed orders of convergence and Richardson extrapolation for a sequence of meshes whose
// element size halves from one level to the next (refinement ratio 2).
#pragma once

#include <optional>
#include <vector>

namespace beamrotor {

/// Order p from the errors of two successive levels, e = C h^p: p = log2(coarse / fine).
/// nullopt when either error is zero or not finite (nothing left to measure).
std::optional<double> observedOrder(double coarseError, double fineError);

/// The limit of q(h) estimated from three successive levels q0 (h), q1 (h/2), q2 (h/4).
struct Extrapolation {
  double value = 0;             ///< the estimated exact value
  std::optional<double> order;  ///< the order p it assumed; nullopt: q2 taken as it is
};

/// Richardson extrapolation (L. F. Richardson, Phil. Trans. R. Soc. A 210, 1911; the
/// three-level form with an estimated order as in P. J. Roache, Verification and Validation
/// in Computational Science and Engineering, 1998, ch. 5): p = log2((q1 - q0) / (q2 - q1)),
/// q* = q2 + (q2 - q1) / (2^p - 1). When the differences vanish, change sign or do not
/// shrink (no asymptotic range yet) q2 itself is returned with no order.
Extrapolation richardson(double q0, double q1, double q2);

}  // namespace beamrotor

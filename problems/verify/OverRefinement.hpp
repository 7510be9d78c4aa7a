// Over-refinement: a cantilever's stiffness matrix has a condition number growing like N^4 in
// the element count N, so past some N the round-off of the factorisation outweighs the
// discretisation error and refining makes the answer worse. The study measures both.
#pragma once

#include <vector>

namespace beamrotor::verify {

/// One mesh of the study.
struct RefinementPoint {
  int elements = 0;
  double error = 0;           ///< relative error of the tip deflection against q L^4 / (8 E I)
  double discretisation = 0;  ///< the exact discretisation part of it, 1 / (3 N^2)
  double rcond = 0;           ///< CHOLMOD's reciprocal condition estimate of the factor
  double seconds = 0;         ///< wall time of the solve
  bool warned = false;        ///< whether `beamrotor solve` would warn (OverRefinementWarning)
};

/// A steel cantilever (1 m, 20 x 20 mm) under a uniform load applied as nodal forces q h
/// (q h / 2 at the ends), Euler-Bernoulli elements, solved once per element count.
std::vector<RefinementPoint> overRefinementStudy(const std::vector<int>& elementCounts);

}  // namespace beamrotor::verify

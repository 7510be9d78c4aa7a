// Repeated eigenvalues: a square-section beam simply supported in both bending planes has
// every bending frequency twice. Any basis of each 2-D eigenspace is a correct answer, so the
// computed vectors are compared with the exact ones as subspaces (principal angles, Golub and
// Van Loan, Matrix Computations, 6.4.3), not vector by vector.
#pragma once

#include <vector>

namespace beamrotor::verify {

struct ClusterPoint {
  int order = 0;               ///< n: the pair of modes sin(n pi x / L) in both planes
  double relFrequencyGap = 0;  ///< |f_a - f_b| / f of the computed pair
  double subspaceAngle = 0;    ///< largest principal angle, computed vs exact span (rad)
  double vectorAngle = 0;      ///< angle of the first computed vector to the exact y-plane
                               ///< shape (rad): arbitrary within the eigenspace
};

/// The first `pairs` bending pairs of a 2 m steel square tube beam of 60 elements (3D).
std::vector<ClusterPoint> eigenClusterStudy(int pairs);

}  // namespace beamrotor::verify

// Load factors of linear buckling: the lambda with (K + lambda KG) x = 0, K the (positive
// definite) stiffness of a supported structure, KG the geometric stiffness of a reference
// state (indefinite: compressed members soften, tensioned ones stiffen). With mu = 1 / lambda
// this is the symmetric problem -KG x = mu K x whose inner-product matrix K is positive
// definite, so Lanczos runs in K's inner product (ARPACK mode 2, the idea behind its buckling
// mode): the largest mu are the smallest positive load factors, the most negative mu the
// negative factors of least magnitude (the load reversed). Small problems go to a dense solver.
#pragma once

#include <Eigen/Dense>

#include "fem/assembly/Assembly.hpp"

namespace beamrotor {

struct BucklingPairs {
  Eigen::VectorXd factors;  ///< load factors lambda, ascending in |lambda|
  Eigen::MatrixXd vectors;  ///< K-orthonormal columns (x^T K x = 1)
  double factorEntries = 0;  ///< fill of the factor of K (0 for the dense path)
};

/// Up to `count` positive load factors of least magnitude (sign +1) or negative ones of least
/// magnitude (sign -1); fewer when the reference state has fewer (none when nothing is
/// compressed). Throws SolveError when K is not positive definite (a mechanism) or ARPACK fails.
BucklingPairs bucklingEigenpairs(const SparseMatrix& K, const SparseMatrix& KG, int count,
                                 int sign);

}  // namespace beamrotor

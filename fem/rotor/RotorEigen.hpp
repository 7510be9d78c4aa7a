// Eigenpairs of the quadratic problem of a rotor at one speed,
//   (lambda^2 M + lambda D + K) q = 0,      D = C + Omega G,
// nearest a shift sigma, through the first-order (state-space) form with x = (q, lambda q):
//   A x = lambda B x,   A = [0 I; -K -D],   B = [I 0; 0 M].
// Shift-invert: ARPACK's Arnoldi iteration (dnaupd/dneupd for a real shift, znaupd/zneupd for
// a complex one) finds the largest nu of OP = (A - sigma B)^-1 B, and lambda = sigma + 1/nu.
// OP is applied by block elimination of A - sigma B: with P(sigma) = K + sigma D + sigma^2 M,
//   y1 = -P^-1 (M x2 + (D + sigma M) x1),   y2 = x1 + sigma y1,
// so only the n x n sparse P is factorised (UMFPACK), never a 2n x 2n or dense matrix. A
// singular M (shafts without rotary inertia) only adds infinite eigenvalues (nu = 0), which
// the iteration never picks. Small systems go to a dense solver of the same operator.
#pragma once

#include <Eigen/Dense>
#include <complex>
#include <memory>

#include "fem/assembly/Assembly.hpp"

namespace beamrotor {

enum class EigenMethod {
  automatic,  ///< dense below 200 state variables, Arnoldi above
  dense,      ///< dense eigensolver of OP (small systems, tests)
  arnoldi,    ///< ARPACK shift-invert
};

struct QuadraticEigenpairs {
  Eigen::VectorXcd values;   ///< lambda (1/s), nearest the shift first
  Eigen::MatrixXcd vectors;  ///< the displacement parts q (free dofs), unit Euclidean norm
  double factorEntries = 0;  ///< LU fill of P(sigma) (0 for the dense path)
};

/// Keeps the sparse factorisation between calls: a sweep over speeds, whose P(sigma) share one
/// pattern, does the symbolic analysis once.
class QuadraticEigenSolver {
 public:
  QuadraticEigenSolver();
  ~QuadraticEigenSolver();

  /// The `count` eigenpairs (state eigenvalues: a lightly damped mode is a conjugate pair,
  /// two of them) nearest `shift` (1/s). K, D, M real, any symmetry. Throws SolveError when
  /// P(shift) is singular (shift 0 with a rigid-body mode) or ARPACK fails.
  QuadraticEigenpairs solve(const SparseMatrix& K, const SparseMatrix& D, const SparseMatrix& M,
                            int count, std::complex<double> shift,
                            EigenMethod method = EigenMethod::automatic);
  /// Symbolic analyses done so far (1 per distinct pattern and scalar type).
  int analyses() const;

 private:
  struct Factors;
  std::unique_ptr<Factors> factors_;
};

}  // namespace beamrotor

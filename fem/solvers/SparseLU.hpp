// UMFPACK through Eigen's wrapper, plus what the wrapper keeps to itself: UMFPACK's
// reciprocal condition estimate (min |U_ii| / max |U_ii| after its row scaling), which tells a
// singular or nearly singular matrix apart from a healthy one before its solution is trusted.
// Row scaling leaves the columns (the dofs' units) as they are: LinearSolver factorises the
// symmetrically scaled matrix, so that its estimate does not depend on them.
#pragma once

#include <Eigen/UmfPackSupport>

#include "fem/assembly/Assembly.hpp"
#include "fem/solvers/Tolerances.hpp"

namespace beamrotor {

class SparseLU : public Eigen::UmfPackLU<SparseMatrix> {
 public:
  /// UMFPACK's cheap reciprocal condition estimate of the last numeric factorisation
  /// (0 for an exactly singular matrix).
  double rcond() const { return m_umfpackInfo[UMFPACK_RCOND]; }
  /// True when the factorisation succeeded and rcond is above tol.
  bool healthy(double tol) const { return info() == Eigen::Success && rcond() > tol; }
  /// Fill-in: entries in L plus U.
  double factorEntries() const { return m_umfpackInfo[UMFPACK_LNZ] + m_umfpackInfo[UMFPACK_UNZ]; }
  /// The column ordering UMFPACK's symbolic analysis used ("AMD/COLAMD", "METIS", ...).
  const char* orderingName() const {
    switch (int(m_umfpackInfo[UMFPACK_ORDERING_USED])) {
      case UMFPACK_ORDERING_AMD:
        return "AMD/COLAMD";
      case UMFPACK_ORDERING_METIS:
        return "METIS";
      case UMFPACK_ORDERING_NONE:
        return "natural";
      case UMFPACK_ORDERING_GIVEN:
        return "given";
      default:
        return "UMFPACK's";
    }
  }
};

}  // namespace beamrotor

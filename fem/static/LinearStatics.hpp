// The linear static system of a model with supports eliminated, factorised so that it can be
// solved again with some free dofs held at given values (active contacts) without a new
// symbolic analysis: held dofs keep their place in the matrix, their rows and columns are
// replaced by the diagonal, so the sparsity pattern never changes. K is stored as a band
// and factorised by LAPACK's banded Cholesky when its free equations couple only near the
// diagonal (a line numbered node by node: fem/assembly/BandAssembly), else sparse and
// factorised by CHOLMOD or UMFPACK (fem/solvers/LinearSolver).
#pragma once

#include <string>
#include <utility>
#include <vector>

#include "fem/assembly/Assembly.hpp"
#include "fem/assembly/RigidTies.hpp"
#include "fem/model/Model.hpp"
#include "fem/assembly/SymmetricBand.hpp"
#include "fem/model/Results.hpp"
#include "fem/solvers/BandCholesky.hpp"
#include "fem/solvers/LinearSolver.hpp"
#include "fem/solvers/SymbolicReuse.hpp"

namespace beamrotor {

/// A free equation held at a value (m or rad).
struct HeldDof {
  int equation = -1;
  double value = 0;
};

class LinearStatics {
 public:
  /// Numbers the dofs and assembles K (free-free), the loads and the prescribed values. With
  /// `reuse`, K is factorised by its solver (the symbolic analysis of an earlier system of the
  /// same pattern kept); it must outlive this object and serve no other system meanwhile.
  explicit LinearStatics(const Model& model, SymbolicReuse* reuse = nullptr);

  /// Full-length displacement with the supports at their prescribed values and the held dofs
  /// at theirs. Throws UnsupportedStructure for a mechanism (named), SolveError for a held
  /// structure whose solution is not finite; otherwise roundOff() says how much of it holds.
  Eigen::VectorXd solve(const std::vector<HeldDof>& held, double singularRcond);

  /// Replaces the loads (point and span loads) by `loading`'s, a load case on this model
  /// (fem/model/Loading.hpp), which must outlive the solves and reactions that use it, or by
  /// the model's own when null; the next solve without held dofs reuses the factor.
  /// Prescribed values stay the model's.
  void setLoads(const Loading* loading);

  /// Full-length K u - f: at a constrained or held dof, the force its support or stop exerts.
  Eigen::VectorXd residual(const Eigen::VectorXd& u) const;
  /// The same at the constrained dofs alone (entry k for equation freeCount + k): the support
  /// reactions, from the elements that touch a support.
  Eigen::VectorXd reactions(const Eigen::VectorXd& u) const;

  /// Frees K and the band's factor once no more solves will come (a static run's memory
  /// peaks when the nodal field is made beside them: 10^6 planar elements, 46 MB of field
  /// beside 240 MB of matrices). residual(), reactions() and the diagnostics below stay; a
  /// later solve() throws std::logic_error. A sparse factor stays with its solver, which a
  /// SymbolicReuse may share with other systems.
  void releaseMatrices();

  const DofMap& dofs() const { return dofs_; }
  /// Stored entries of K (free-free, both triangles, without exact zeros off the diagonal).
  long long stiffnessEntries() const { return stiffnessEntries_; }
  /// Reciprocal condition estimate of the last factorisation, symmetrically scaled.
  double rcond() const { return rcond_; }
  /// The measured relative error of the last solution (round-off): the residual in extended
  /// precision and one correction solve, in the scaled metric sqrt(K_jj) |u_j|.
  double roundOff() const { return roundOff_; }
  double factorEntries() const { return factorEntries_; }
  /// The direct method chosen for K and its ordering ("CHOLMOD LDL', AMD ordering").
  std::string solverName() const { return solverName_; }
  /// Seconds spent factorising and solving so far.
  double factorSeconds() const { return factorSeconds_; }
  double solveSeconds() const { return solveSeconds_; }

 private:
  const Model& model_;
  const Loading* loading_ = nullptr;  ///< the loads on the right-hand side; null: the model's
  DofMap dofs_;
  bool banded_ = false;  ///< K is bandK_ (factorised by bandFactor_), else K_
  SymmetricBand bandK_;
  BandCholesky bandFactor_;
  SparseMatrix K_;
  MatrixSymmetry symmetry_ = MatrixSymmetry::unknown;  ///< of K_, known from its elements
  Eigen::VectorXd rhs_;  ///< the free equations' loads less K_fc u_c (prescribed values)
  /// Rigid ties eliminated (RigidTies.hpp); K_ and rhs_ are then the reduced ones (the
  /// sparse path always).
  TieReduction ties_;
  /// The reduced right-hand side of full-length loads f: its free part less K_fc u_c, times T'.
  Eigen::VectorXd reducedLoads(Eigen::VectorXd f) const;
  SymbolicReuse* reuse_;
  LinearSolver ownSolver_;
  LinearSolver* solver_ = &ownSolver_;  ///< ownSolver_, or reuse_'s once analysed
  bool analysed_ = false;
  bool factoredUnheld_ = false;  ///< the factor is of K itself (no held dofs)
  bool released_ = false;
  double rcond_ = 0, roundOff_ = 0, factorSeconds_ = 0, solveSeconds_ = 0;
  // Set where K, its analysis and its last factorisation are made; kept past
  // releaseMatrices().
  long long stiffnessEntries_ = 0;
  double factorEntries_ = 0;
  std::string solverName_;
};

}  // namespace beamrotor

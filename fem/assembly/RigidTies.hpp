// The exact elimination of rigid ties (Model::rigidTies: rigid links, member end offsets,
// diaphragms): every tied slave dof is a combination of its master's dofs, u_s = sum c_j u_j,
// so a free-free K and its loads reduce to K_r = T' K T and f_r = T' f (master-slave
// elimination; e.g. Cook, Malkus, Plesha and Witt, Concepts and Applications of Finite
// Element Analysis, 4th ed., sec. 9.2). The equations keep their numbers: a slave's row and
// column of K_r hold only a diagonal, its load is zero, and T u_r gives it back its value.
#pragma once

#include <array>
#include <vector>

#include "fem/assembly/Assembly.hpp"

namespace beamrotor {

/// One term of a tied dof: coefficient times the value of equation `equation` (a master dof,
/// free or constrained).
struct TieTerm {
  int equation = -1;
  double coefficient = 0;
};

/// A slave's free equation and the master terms it equals.
struct TiedEquation {
  int equation = -1;
  std::vector<TieTerm> terms;
};

/// The tied equations of model's rigid ties, in tie order. A chain (a follower that leads
/// another tie) is resolved into terms on the equations that follow nothing: the rigid
/// motions composed. Throws std::invalid_argument naming the tie when a slave dof is missing
/// or held by a support or tied twice, when the ties form a loop, or when its master lacks a
/// dof the motion needs or has a support that prescribes a value other than zero.
std::vector<TiedEquation> tiedEquations(const Model& model, const DofMap& dofs);

/// T (freeCount x freeCount): the identity on the independent free equations, each tied one's
/// row its free master terms, the tied columns zero. u_free = T u_r.
SparseMatrix tieTransformation(const std::vector<TiedEquation>& tied, int freeCount);

/// T' K T with each tied equation's diagonal set to `K`'s own there (1 where that is not
/// positive), so that the reduced matrix stays nonsingular and its scaling sensible.
SparseMatrix tiedStiffness(const SparseMatrix& K, const SparseMatrix& T,
                           const std::vector<TiedEquation>& tied);

/// A model's ties applied to its free-free matrices and vectors in their own numbering (the
/// statics' form, for the dynamics and stability solvers): with u_free = T q, a stiffness
/// becomes tiedStiffness's, a mass, damping or geometric stiffness T' A T (the tied rows and
/// columns zero, so the tied equations carry an infinite eigenvalue the eigensolvers drop),
/// a load T' f; a reduced solution or eigenvector q expands back as T q.
class TieReduction {
 public:
  TieReduction(const Model& model, const DofMap& dofs);
  bool empty() const { return tied_.empty(); }
  const std::vector<TiedEquation>& tied() const { return tied_; }
  /// The tied equations' numbers (for the mechanism finder, which counts them as held).
  std::vector<int> tiedNumbers() const;
  /// K itself without ties; else T' K T with the tied diagonals kept.
  SparseMatrix stiffness(const SparseMatrix& K) const;
  /// A itself without ties; else T' A T.
  SparseMatrix projected(const SparseMatrix& A) const;
  /// The geometric stiffness of a state: the elements' KG projected (T' KG T), plus each
  /// tie's own. A rigid arm r from master to follower carrying the force F at its follower
  /// moves it by theta x r + theta x (theta x r) / 2 to second order in the master's turn
  /// theta, so F does the work theta' ((F.r) I - (F r' + r F') / 2) theta / 2 less: that
  /// matrix on the master's rotations (a load F on a column's rigid cap of height e adds
  /// -F e to the column top's turn, the cap's P-delta). `residual` is the state's
  /// full-length K u - f (with KG in it for a second-order state), whose negative at a
  /// follower's tied translations is F.
  SparseMatrix geometric(const SparseMatrix& KG, const Eigen::VectorXd& residual) const;
  /// f itself without ties; else T' f (free-length, or the free part of a full-length f).
  Eigen::VectorXd loads(const Eigen::VectorXd& f) const;
  /// q itself without ties; else T q, column by column (free-length rows).
  Eigen::MatrixXd expand(const Eigen::MatrixXd& q) const;
  Eigen::VectorXcd expand(const Eigen::VectorXcd& q) const;

 private:
  /// One tie's arm: its master's rotation equations (free ones; -1 otherwise), its
  /// follower's tied translation equations (-1 where untied) and x_s - x_m; in a chain, the
  /// master is the first one the follower moves with as one body.
  struct Arm {
    std::array<int, 3> masterRotation{-1, -1, -1};
    std::array<int, 3> followerTranslation{-1, -1, -1};
    Eigen::Vector3d r = Eigen::Vector3d::Zero();
  };
  std::vector<TiedEquation> tied_;
  std::vector<Arm> arms_;
  SparseMatrix T_;
};

/// The full-length K u - f of a first-order state u under the model's own loads (at a tied
/// follower, what its tie holds it with).
Eigen::VectorXd stateResidual(const Model& model, const DofMap& dofs, const Eigen::VectorXd& u);

/// The forces the ties carry to constrained masters: for each tied equation s and each of its
/// terms on a constrained equation j, coefficient times r[s] added to out[j - freeCount]. r
/// is the full-length K u - f, whose entry at a slave is what the tie holds it with.
void addTiedReactions(const std::vector<TiedEquation>& tied, const DofMap& dofs,
                      const Eigen::VectorXd& r, Eigen::VectorXd& out);

}  // namespace beamrotor

// The exact elimination of rigid ties (Model::rigidTies: rigid links, member end offsets,
// diaphragms): every tied slave dof is a combination of its master's dofs, u_s = sum c_j u_j,
// so a free-free K and its loads reduce to K_r = T' K T and f_r = T' f (master-slave
// elimination; e.g. Cook, Malkus, Plesha and Witt, Concepts and Applications of Finite
// Element Analysis, 4th ed., sec. 9.2). The equations keep their numbers: a slave's row and
// column of K_r hold only a diagonal, its load is zero, and T u_r gives it back its value.
#pragma once

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

/// The tied equations of model's rigid ties, in tie order. Throws std::invalid_argument
/// naming the tie when a slave dof is missing or held by a support, tied twice, or itself a
/// master of another tie (a chain), or when its master lacks a dof the motion needs or has a
/// support that prescribes a value other than zero.
std::vector<TiedEquation> tiedEquations(const Model& model, const DofMap& dofs);

/// T (freeCount x freeCount): the identity on the independent free equations, each tied one's
/// row its free master terms, the tied columns zero. u_free = T u_r.
SparseMatrix tieTransformation(const std::vector<TiedEquation>& tied, int freeCount);

/// T' K T with each tied equation's diagonal set to `K`'s own there (1 where that is not
/// positive), so that the reduced matrix stays nonsingular and its scaling sensible.
SparseMatrix tiedStiffness(const SparseMatrix& K, const SparseMatrix& T,
                           const std::vector<TiedEquation>& tied);

/// The forces the ties carry to constrained masters: for each tied equation s and each of its
/// terms on a constrained equation j, coefficient times r[s] added to out[j - freeCount]. r
/// is the full-length K u - f, whose entry at a slave is what the tie holds it with.
void addTiedReactions(const std::vector<TiedEquation>& tied, const DofMap& dofs,
                      const Eigen::VectorXd& r, Eigen::VectorXd& out);

}  // namespace beamrotor

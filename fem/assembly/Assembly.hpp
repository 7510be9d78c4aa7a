// Sparse assembly of the free-free block of K, M, C or G, with the sparsity pattern computed
// once from the connectivity and reused for every matrix (and every re-assembly in a sweep).
#pragma once

#include <Eigen/Sparse>
#include <array>
#include <utility>
#include <vector>

#include "fem/model/DofMap.hpp"
#include "fem/model/Element.hpp"
#include "fem/model/Loading.hpp"

namespace beamrotor {

class Model;
using SparseMatrix = Eigen::SparseMatrix<double, Eigen::ColMajor, int>;

enum class MatrixKind { stiffness, mass, damping, gyroscopic };

class SparseAssembler {
 public:
  /// Computes the pattern of the free-free block: dof pairs of nodes that share an element.
  SparseAssembler(const Model& model, const DofMap& dofs);

  /// The free-free block of one global matrix (freeCount x freeCount, compressed).
  SparseMatrix assemble(MatrixKind kind) const&;
  /// The same from a temporary assembler: its pattern is filled in place, not copied.
  SparseMatrix assemble(MatrixKind kind) &&;
  /// Two global matrices (the modal path's K and M) in one pass over the elements, each
  /// entry's place in the pattern found once for both; the second fills the pattern in place.
  std::pair<SparseMatrix, SparseMatrix> assemble(MatrixKind first, MatrixKind second) &&;
  /// The free-free block of the geometric stiffness of the section forces of the full-length
  /// displacement u (ordered as DofMap): the initial-stress matrix of that state.
  SparseMatrix assembleGeometric(const Eigen::VectorXd& u) const;
  /// Number of stored entries of the pattern.
  long long patternSize() const { return pattern_.nonZeros(); }
  /// True when every element says its stiffness is symmetric (Element::symmetricStiffness):
  /// the assembled K is then symmetric by construction, up to its entries' round-off.
  bool stiffnessSymmetric() const { return stiffnessSymmetric_; }

 private:
  /// Adds every element's matrix of one kind into A, which has the pattern's structure.
  void fill(SparseMatrix& A, MatrixKind kind) const;
  /// Adds the i-th of matricesOf(element) into *targets[i] for every element (empty matrices
  /// skipped); the targets have the pattern's structure. With `reuseForEqual` the matrices
  /// of a run of equal elements are computed once (ReusedForEqual): not for matrices of a
  /// displacement state, which differ from element to element.
  template <std::size_t N, class MatricesOf>
  void fillWith(const std::array<SparseMatrix*, N>& targets, bool reuseForEqual,
                MatricesOf&& matricesOf) const;

  const Model& model_;
  const DofMap& dofs_;
  SparseMatrix pattern_;  // compressed free-free block with every value zero
  // Free equations are numbered node by node: node i's are [freeBegin_[i], freeBegin_[i + 1]).
  std::vector<int> freeBegin_;
  bool stiffnessSymmetric_ = true;
};

/// Removes A's off-diagonal entries that are exactly zero (A unchanged when it has none). An
/// assembled pattern holds every dof pair of nodes that share an element, but many such pairs
/// never couple: a member along a global axis keeps its axial, in-plane and out-of-plane dofs
/// apart, so a flat grillage's K is two independent systems and a straight line's axial dofs
/// are a chain of their own. Factorising without those entries gives the same solution with
/// a half or a third of the fill and flops (see the performance issue's closing notes).
/// Diagonal entries stay, so that a dof keeps its place in the pattern. What is kept is
/// copied into storage of its own size, part by part, and the old storage is released.
void dropExactZeros(SparseMatrix& A);

/// Writes the equations of e's dofs into eq (in the order of e.dofs()); true when owned(eq)
/// holds for any of them: a part's test of whether an element adds to its range.
template <class Owned>
bool elementEquations(const Element& e, const DofMap& dofs, std::array<int, kMaxElementDofs>& eq,
                      Owned&& owned) {
  bool any = false;
  const auto d = e.dofs();
  for (std::size_t a = 0; a < d.size(); ++a) {
    eq[a] = dofs.equation(d[a]);
    any = any || owned(eq[a]);
  }
  return any;
}

/// One element quantity (a matrix of one kind, the load) computed once for a run of equal
/// elements (Element::sameMatricesAs): a uniform segment's beams have the same matrices, and
/// computing them is most of an assembly pass. Each part of a pass keeps one of these.
template <class Value>
class ReusedForEqual {
 public:
  template <class Compute>
  const Value& of(const Element& e, Compute&& compute) {
    if (last_ == nullptr || (last_ != &e && !e.sameMatricesAs(*last_))) value_ = compute(e);
    last_ = &e;
    return value_;
  }

 private:
  const Element* last_ = nullptr;
  Value value_{};
};

/// True when every element says its stiffness is symmetric (Element::symmetricStiffness).
bool stiffnessSymmetricByConstruction(const Model& model);

/// The element matrix of one kind (empty when the element has none).
ElementMatrix elementMatrix(const Element& e, MatrixKind kind);

/// Gathers an element's dof values from a full-length vector (ordered as DofMap).
ElementVector gather(const Element& e, const DofMap& dofs, const Eigen::VectorXd& u);

/// Full-length vector of the concentrated nodal loads alone.
Eigen::VectorXd nodalLoadVector(const Model& model, const DofMap& dofs);

/// Full-length vector of applied loads: nodal loads plus element equivalent loads.
Eigen::VectorXd loadVector(const Model& model, const DofMap& dofs);

/// Full-length vector of a loading's loads on the model (a load case, fem/model/Loading.hpp):
/// its point loads plus its span loads' equivalent nodal loads.
Eigen::VectorXd loadVector(const Model& model, const DofMap& dofs, const Loading& loading);

/// Full-length vector of the element forces K u - f_elem for a full-length displacement u;
/// at a constrained dof, this minus the nodal loads there is the support reaction.
Eigen::VectorXd elementForces(const Model& model, const DofMap& dofs, const Eigen::VectorXd& u);
/// The same with each element's load that of `loading` in place of its own.
Eigen::VectorXd elementForces(const Model& model, const DofMap& dofs, const Eigen::VectorXd& u,
                              const Loading& loading);

/// The same at the constrained dofs alone (entry k for equation freeCount + k), from the
/// elements that touch one: a large model's reactions in the time of its supported elements.
Eigen::VectorXd constrainedElementForces(const Model& model, const DofMap& dofs,
                                         const Eigen::VectorXd& u);
/// The same with each element's load that of `loading` in place of its own.
Eigen::VectorXd constrainedElementForces(const Model& model, const DofMap& dofs,
                                         const Eigen::VectorXd& u, const Loading& loading);

}  // namespace beamrotor

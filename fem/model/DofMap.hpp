// DofMap: (node, dof kind) -> equation number. Only dofs some element or support touches
// exist. Free dofs are numbered first (0 .. freeCount-1, node by node so the matrix stays
// banded), constrained dofs after them (freeCount .. size-1). All global index arithmetic
// lives here.
#pragma once

#include <array>
#include <vector>

#include "fem/model/Dof.hpp"

namespace beamrotor {

class Model;

class DofMap {
 public:
  /// Numbers the dofs of every element and support of model.
  explicit DofMap(const Model& model);

  /// Equation number of (node, dof), or -1 when the model has no such dof.
  int equation(int node, Dof d) const { return slots_[node][dofIndex(d)]; }
  int equation(const NodeDof& d) const { return equation(d.node, d.dof); }
  /// The dof behind an equation number.
  const NodeDof& dofOf(int equation) const { return dofs_[equation]; }

  bool isFree(int equation) const { return equation >= 0 && equation < freeCount_; }
  bool isConstrained(int equation) const { return equation >= freeCount_; }
  int freeCount() const { return freeCount_; }
  /// The node of each free equation, in equation order (a node's equations are consecutive).
  std::vector<int> freeNodes() const;
  int constrainedCount() const { return size() - freeCount_; }
  int size() const { return int(dofs_.size()); }

 private:
  std::vector<std::array<int, kDofKinds>> slots_;
  std::vector<NodeDof> dofs_;
  int freeCount_ = 0;
};

}  // namespace beamrotor

#include "fem/assembly/Assembly.hpp"

#include <algorithm>
#include <stdexcept>

#include "fem/assembly/CompressedPattern.hpp"
#include "fem/model/Model.hpp"

namespace beamrotor {

namespace {

/// Node adjacency (each node lists itself and every node it shares an element with), as
/// compressed rows with sorted, unique entries.
void nodeAdjacency(const Model& model, std::vector<int>& start, std::vector<int>& adj) {
  const int n = model.nodeCount();
  std::vector<int> count(n + 1, 0);
  std::array<int, kMaxElementDofs> nodes{};
  auto elementNodes = [&](const Element& e) {
    int k = 0;
    for (const NodeDof& d : e.dofs())
      if (std::find(nodes.begin(), nodes.begin() + k, d.node) == nodes.begin() + k)
        nodes[k++] = d.node;
    return k;
  };
  for (const auto& e : model.elements()) {
    const int k = elementNodes(*e);
    for (int a = 0; a < k; ++a) count[nodes[a] + 1] += k;
  }
  for (int i = 0; i < n; ++i) count[i + 1] += count[i] + 1;  // +1: the node itself
  std::vector<int> fill(count.begin(), count.end() - 1);
  adj.assign(count[n], 0);
  for (int i = 0; i < n; ++i) adj[fill[i]++] = i;
  for (const auto& e : model.elements()) {
    const int k = elementNodes(*e);
    for (int a = 0; a < k; ++a)
      for (int b = 0; b < k; ++b) adj[fill[nodes[a]]++] = nodes[b];
  }
  // Sort and deduplicate each node's list in place, compacting as we go.
  start.assign(n + 1, 0);
  int out = 0;
  for (int i = 0; i < n; ++i) {
    auto first = adj.begin() + count[i], last = adj.begin() + count[i + 1];
    std::sort(first, last);
    last = std::unique(first, last);
    start[i] = out;
    out = int(std::copy(first, last, adj.begin() + out) - adj.begin());
  }
  start[n] = out;
  adj.resize(out);
}

/// Position of (row, col) in the value array of a compressed matrix holding that entry.
int slot(const SparseMatrix& A, int row, int col) {
  const int* rows = A.innerIndexPtr();
  const int* first = rows + A.outerIndexPtr()[col];
  const int* last = rows + A.outerIndexPtr()[col + 1];
  return int(std::lower_bound(first, last, row) - rows);
}

}  // namespace

SparseAssembler::SparseAssembler(const Model& model, const DofMap& dofs)
    : model_(model), dofs_(dofs) {
  std::vector<int> start, adj;
  nodeAdjacency(model, start, adj);
  // Free equations are numbered node by node, so walking a column's neighbour nodes in
  // ascending order yields ascending row numbers. Count first, then fill in place.
  const int nf = dofs.freeCount();
  auto forEachRow = [&](int col, auto&& visit) {
    const int node = dofs.dofOf(col).node;
    for (int k = start[node]; k < start[node + 1]; ++k)
      for (Dof d : kAllDofs) {
        const int row = dofs.equation(adj[k], d);
        if (dofs.isFree(row)) visit(row);
      }
  };
  compressedPattern(nf, nf, forEachRow).swap(pattern_);  // no copy: Eigen has no move assignment
  stiffnessSymmetric_ = std::all_of(model.elements().begin(), model.elements().end(),
                                    [](const auto& e) { return e->symmetricStiffness(); });
}

ElementMatrix elementMatrix(const Element& e, MatrixKind kind) {
  switch (kind) {
    case MatrixKind::stiffness:
      return e.stiffness();
    case MatrixKind::mass:
      return e.mass();
    case MatrixKind::damping:
      return e.damping();
    case MatrixKind::gyroscopic:
      return e.gyroscopic();
  }
  return {};
}

SparseMatrix SparseAssembler::assemble(MatrixKind kind) const& {
  SparseMatrix A = pattern_;
  fill(A, kind);
  return A;
}

SparseMatrix SparseAssembler::assemble(MatrixKind kind) && {
  SparseMatrix A;
  A.swap(pattern_);  // this assembler is not used again (Eigen 3.4 sparse has no move)
  fill(A, kind);
  return A;
}

std::pair<SparseMatrix, SparseMatrix> SparseAssembler::assemble(MatrixKind first,
                                                               MatrixKind second) && {
  std::pair<SparseMatrix, SparseMatrix> out;
  out.first = pattern_;
  out.second.swap(pattern_);  // this assembler is not used again
  fillWith<2>({&out.first, &out.second}, [&](const Element& e) {
    return std::array<ElementMatrix, 2>{elementMatrix(e, first), elementMatrix(e, second)};
  });
  return out;
}

SparseMatrix SparseAssembler::assembleGeometric(const Eigen::VectorXd& u) const {
  SparseMatrix A = pattern_;
  fillWith<1>({&A}, [&](const Element& e) {
    return std::array<ElementMatrix, 1>{e.geometricStiffness(gather(e, dofs_, u))};
  });
  return A;
}

void SparseAssembler::fill(SparseMatrix& A, MatrixKind kind) const {
  fillWith<1>({&A},
              [&](const Element& e) { return std::array<ElementMatrix, 1>{elementMatrix(e, kind)}; });
}

template <std::size_t N, class MatricesOf>
void SparseAssembler::fillWith(const std::array<SparseMatrix*, N>& targets,
                               MatricesOf&& matricesOf) const {
  std::array<double*, N> values;
  for (std::size_t i = 0; i < N; ++i) values[i] = targets[i]->valuePtr();
  const SparseMatrix& structure = *targets[0];
  std::array<int, kMaxElementDofs> eq{};
  for (const auto& e : model_.elements()) {
    const std::array<ElementMatrix, N> matrices = matricesOf(*e);
    if (std::all_of(matrices.begin(), matrices.end(),
                    [](const ElementMatrix& m) { return m.size() == 0; }))
      continue;
    const auto d = e->dofs();
    const int n = int(d.size());
    for (int a = 0; a < n; ++a) eq[a] = dofs_.equation(d[a]);
    for (int b = 0; b < n; ++b) {
      if (!dofs_.isFree(eq[b])) continue;
      for (int a = 0; a < n; ++a) {
        if (!dofs_.isFree(eq[a])) continue;
        int place = -1;  // found once, for the first matrix with an entry here
        for (std::size_t i = 0; i < N; ++i) {
          const ElementMatrix& m = matrices[i];
          if (m.size() == 0 || m(a, b) == 0.0) continue;
          if (place < 0) place = slot(structure, eq[a], eq[b]);
          values[i][place] += m(a, b);
        }
      }
    }
  }
}

ElementVector gather(const Element& e, const DofMap& dofs, const Eigen::VectorXd& u) {
  const auto d = e.dofs();
  ElementVector ue(d.size());
  for (int a = 0; a < int(d.size()); ++a) ue[a] = u[dofs.equation(d[a])];
  return ue;
}

Eigen::VectorXd nodalLoadVector(const Model& model, const DofMap& dofs) {
  Eigen::VectorXd f = Eigen::VectorXd::Zero(dofs.size());
  for (const NodalLoad& l : model.loads()) {
    const int eq = dofs.equation(l.node, l.dof);
    if (eq < 0)
      throw std::invalid_argument("a load acts on " + model.describe({l.node, l.dof}) +
                                  ", which no element carries");
    f[eq] += l.value;
  }
  return f;
}

Eigen::VectorXd loadVector(const Model& model, const DofMap& dofs) {
  Eigen::VectorXd f = nodalLoadVector(model, dofs);
  for (const auto& e : model.elements()) {
    const ElementVector fe = e->load();
    if (fe.size() == 0) continue;
    const auto d = e->dofs();
    for (int a = 0; a < int(d.size()); ++a) f[dofs.equation(d[a])] += fe[a];
  }
  return f;
}

Eigen::VectorXd elementForces(const Model& model, const DofMap& dofs, const Eigen::VectorXd& u,
                              bool constrainedOnly) {
  Eigen::VectorXd r = Eigen::VectorXd::Zero(dofs.size());
  const auto constrained = [&](const NodeDof& d) { return dofs.isConstrained(dofs.equation(d)); };
  for (const auto& e : model.elements()) {
    const auto d = e->dofs();
    if (constrainedOnly && std::none_of(d.begin(), d.end(), constrained)) continue;
    const ElementVector fe = e->endForces(gather(*e, dofs, u));
    for (int a = 0; a < int(d.size()); ++a) r[dofs.equation(d[a])] += fe[a];
  }
  return r;
}

void dropExactZeros(SparseMatrix& A) {
  A.prune([](int row, int col, double value) { return value != 0 || row == col; });
  A.data().squeeze();
}

}  // namespace beamrotor

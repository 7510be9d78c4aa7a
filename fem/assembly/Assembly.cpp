#include "fem/assembly/Assembly.hpp"

#include <algorithm>
#include <limits>
#include <stdexcept>
#include <utility>

#include "fem/assembly/ParallelParts.hpp"
#include "fem/model/Model.hpp"

namespace beamrotor {

namespace {

/// Column bounds 0 = c_0 <= c_1 <= ... <= c_parts = cols splitting A's entries evenly.
std::vector<int> balancedColumnRanges(const SparseMatrix& A, int parts) {
  std::vector<int> bounds(parts + 1, int(A.cols()));
  bounds[0] = 0;
  const int* colStart = A.outerIndexPtr();
  for (int p = 1; p < parts; ++p) {
    const long long wanted = A.nonZeros() * p / parts;
    bounds[p] = int(std::lower_bound(colStart, colStart + A.cols(), wanted) - colStart);
  }
  return bounds;
}

/// Node adjacency (each node lists itself and every node it shares an element with), as
/// compressed rows with sorted, unique entries. Built part by part: each part counts and
/// writes the entries of its own range of elements into its own place in every node's list.
void nodeAdjacency(const Model& model, std::vector<int>& start, std::vector<int>& adj) {
  const int n = model.nodeCount();
  const auto& elements = model.elements();
  const std::vector<int> bounds = evenRanges(int(elements.size()), partsFor(elements.size()));
  const int parts = int(bounds.size()) - 1;
  const auto forEachElement = [&](int part, auto&& visit) {
    std::array<int, kMaxElementDofs> nodes{};
    for (int i = bounds[part]; i < bounds[part + 1]; ++i) {
      int k = 0;
      for (const NodeDof& d : elements[i]->dofs())
        if (std::find(nodes.begin(), nodes.begin() + k, d.node) == nodes.begin() + k)
          nodes[k++] = d.node;
      visit(nodes, k);
    }
  };
  // 1. What each part adds to each node's list; then where it writes it: after the node
  //    itself and after the parts before it.
  std::vector<std::vector<int>> place(parts, std::vector<int>(n, 0));
  runParts(parts, [&](int part) {
    forEachElement(part, [&](const auto& nodes, int k) {
      for (int a = 0; a < k; ++a) place[part][nodes[a]] += k;
    });
  });
  std::vector<int> listStart(n + 1, 0);
  for (int i = 0; i < n; ++i) {
    int next = listStart[i] + 1;  // +1: the node itself
    for (int part = 0; part < parts; ++part) next += std::exchange(place[part][i], next);
    listStart[i + 1] = next;
  }
  std::vector<int> lists(listStart[n]);
  for (int i = 0; i < n; ++i) lists[listStart[i]] = i;
  runParts(parts, [&](int part) {
    forEachElement(part, [&](const auto& nodes, int k) {
      for (int a = 0; a < k; ++a)
        for (int b = 0; b < k; ++b) lists[place[part][nodes[a]]++] = nodes[b];
    });
  });
  place.clear();
  // 2. Each list sorted and made unique in its place, node range by node range; then the
  //    unique entries packed.
  std::vector<int> unique(n, 0);
  forEvenParts(n, [&](int first, int end) {
    for (int i = first; i < end; ++i) {
      const auto begin = lists.begin() + listStart[i], last = lists.begin() + listStart[i + 1];
      std::sort(begin, last);
      unique[i] = int(std::unique(begin, last) - begin);
    }
  });
  start.assign(n + 1, 0);
  for (int i = 0; i < n; ++i) start[i + 1] = start[i] + unique[i];
  adj.resize(start[n]);
  forEvenParts(n, [&](int first, int end) {
    for (int i = first; i < end; ++i)
      std::copy_n(lists.begin() + listStart[i], unique[i], adj.begin() + start[i]);
  });
}

}  // namespace

SparseAssembler::SparseAssembler(const Model& model, const DofMap& dofs)
    : model_(model), dofs_(dofs) {
  std::vector<int> start, adj;
  nodeAdjacency(model, start, adj);
  // Free equations are numbered node by node, so each node's free equations are one range,
  // [freeBegin[node], freeBegin[node + 1]), and walking a node's neighbours in ascending
  // order yields ascending rows. Every free dof of a node has the same rows: the list is
  // written once for its first column and copied for the others.
  const int nodes = model.nodeCount();
  std::vector<int>& freeBegin = freeBegin_;
  freeBegin.assign(nodes + 1, 0);
  for (int node = 0; node < nodes; ++node) {
    int count = 0;
    for (Dof d : kAllDofs) count += dofs.isFree(dofs.equation(node, d));
    freeBegin[node + 1] = freeBegin[node] + count;
  }
  const auto freeOf = [&](int node) { return freeBegin[node + 1] - freeBegin[node]; };
  // Where each node's columns start among the entries; then the columns, node range by
  // node range.
  std::vector<int> nodeEntries(nodes + 1, 0);
  for (int node = 0; node < nodes; ++node) {
    long long rows = 0;
    for (int k = start[node]; k < start[node + 1]; ++k) rows += freeOf(adj[k]);
    const long long entries = nodeEntries[node] + rows * freeOf(node);
    if (entries > std::numeric_limits<int>::max())
      throw std::length_error("the stiffness pattern has more than 2^31 entries");
    nodeEntries[node + 1] = int(entries);
  }
  const int nf = dofs.freeCount();
  const int entries = nodeEntries[nodes];
  SparseMatrix A(nf, nf);
  A.resizeNonZeros(Eigen::Index(entries));
  int* colStart = A.outerIndexPtr();
  int* rowOf = A.innerIndexPtr();
  forEvenParts(nodes, [&](int firstNode, int endNode) {
    for (int node = firstNode; node < endNode; ++node) {
      if (freeOf(node) == 0) continue;
      const int first = nodeEntries[node];
      int next = first;
      for (int k = start[node]; k < start[node + 1]; ++k)
        for (int row = freeBegin[adj[k]]; row < freeBegin[adj[k] + 1]; ++row) rowOf[next++] = row;
      const int rows = next - first;
      colStart[freeBegin[node]] = first;
      for (int col = freeBegin[node] + 1; col < freeBegin[node + 1]; ++col) {
        colStart[col] = next;
        next = int(std::copy_n(rowOf + first, rows, rowOf + next) - rowOf);
      }
      std::fill(A.valuePtr() + first, A.valuePtr() + next, 0.0);
    }
  });
  colStart[nf] = entries;
  A.swap(pattern_);  // no copy: Eigen has no move assignment
  stiffnessSymmetric_ = stiffnessSymmetricByConstruction(model);
}

bool stiffnessSymmetricByConstruction(const Model& model) {
  return std::all_of(model.elements().begin(), model.elements().end(),
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
  fillWith<2>({&out.first, &out.second}, true, [&](const Element& e) {
    return std::array<ElementMatrix, 2>{elementMatrix(e, first), elementMatrix(e, second)};
  });
  return out;
}

SparseMatrix SparseAssembler::assembleGeometric(const Eigen::VectorXd& u) const {
  SparseMatrix A = pattern_;
  fillWith<1>({&A}, false, [&](const Element& e) {
    return std::array<ElementMatrix, 1>{e.geometricStiffness(gather(e, dofs_, u))};
  });
  return A;
}

void SparseAssembler::fill(SparseMatrix& A, MatrixKind kind) const {
  fillWith<1>({&A}, true, [&](const Element& e) {
    return std::array<ElementMatrix, 1>{elementMatrix(e, kind)};
  });
}

template <std::size_t N, class MatricesOf>
void SparseAssembler::fillWith(const std::array<SparseMatrix*, N>& targets, bool reuseForEqual,
                               MatricesOf&& matricesOf) const {
  std::array<double*, N> values;
  for (std::size_t i = 0; i < N; ++i) values[i] = targets[i]->valuePtr();
  // The targets have the pattern's structure: a column of node p holds, for each neighbour q
  // in ascending order, q's free equations as one block. An entry's place is its column's
  // start, plus the block's offset (found once per pair of the element's nodes), plus the
  // row's place among q's free equations.
  const SparseMatrix& structure = *targets[0];
  const int* colStart = structure.outerIndexPtr();
  const int* rowOf = structure.innerIndexPtr();
  // Each part adds into its own range of columns, element by element in the model's order:
  // every entry is summed in the same order whatever the number of parts (the result is
  // the same to the last bit), and an element whose columns fall in two parts is computed
  // by both.
  const auto fillColumns = [&](int firstColumn, int endColumn) {
    const auto owned = [&](int equation) {
      return equation >= firstColumn && equation < endColumn && dofs_.isFree(equation);
    };
    std::array<int, kMaxElementDofs> eq{}, nodeOf{}, inBlock{}, nodes{};
    std::array<std::array<int, kMaxElementDofs>, kMaxElementDofs> blockAt{};
    ReusedForEqual<std::array<ElementMatrix, N>> reused;
    std::array<ElementMatrix, N> computed;
    for (const auto& e : model_.elements()) {
      if (!elementEquations(*e, dofs_, eq, owned)) continue;
      const auto d = e->dofs();
      const int n = int(d.size());
      const std::array<ElementMatrix, N>& matrices =
          reuseForEqual ? reused.of(*e, matricesOf) : (computed = matricesOf(*e));
      if (std::all_of(matrices.begin(), matrices.end(),
                      [](const ElementMatrix& m) { return m.size() == 0; }))
        continue;
      int k = 0;
      for (int a = 0; a < n; ++a) {
        const int node = d[a].node;
        const int i = int(std::find(nodes.begin(), nodes.begin() + k, node) - nodes.begin());
        if (i == k) nodes[k++] = node;
        nodeOf[a] = i;
        inBlock[a] = eq[a] - freeBegin_[node];
      }
      for (int i = 0; i < k; ++i) {
        const int column = freeBegin_[nodes[i]];
        if (column == freeBegin_[nodes[i] + 1]) continue;  // no free dof: no column
        const int* first = rowOf + colStart[column];
        const int* last = rowOf + colStart[column + 1];
        for (int j = 0; j < k; ++j)
          blockAt[i][j] = int(std::lower_bound(first, last, freeBegin_[nodes[j]]) - first);
      }
      for (int b = 0; b < n; ++b) {
        if (!owned(eq[b])) continue;
        const int column = colStart[eq[b]];
        for (int a = 0; a < n; ++a) {
          if (!dofs_.isFree(eq[a])) continue;
          const int place = column + blockAt[nodeOf[b]][nodeOf[a]] + inBlock[a];
          for (std::size_t i = 0; i < N; ++i) {
            const ElementMatrix& m = matrices[i];
            if (m.size() == 0 || m(a, b) == 0.0) continue;
            values[i][place] += m(a, b);
          }
        }
      }
    }
  };
  const std::vector<int> bounds =
      balancedColumnRanges(structure, partsFor(model_.elements().size()));
  runParts(int(bounds.size()) - 1, [&](int part) { fillColumns(bounds[part], bounds[part + 1]); });
}

ElementVector gather(const Element& e, const DofMap& dofs, const Eigen::VectorXd& u) {
  const auto d = e.dofs();
  ElementVector ue(d.size());
  for (int a = 0; a < int(d.size()); ++a) ue[a] = u[dofs.equation(d[a])];
  return ue;
}

namespace {

/// Full-length vector of point loads on the model's dofs.
Eigen::VectorXd pointLoadVector(const Model& model, const DofMap& dofs,
                                const std::vector<NodalLoad>& loads) {
  Eigen::VectorXd f = Eigen::VectorXd::Zero(dofs.size());
  for (const NodalLoad& l : loads) {
    const int eq = dofs.equation(l.node, l.dof);
    if (eq < 0)
      throw std::invalid_argument("a load acts on " + model.describe({l.node, l.dof}) +
                                  ", which no element carries");
    f[eq] += l.value;
  }
  return f;
}

}  // namespace

Eigen::VectorXd nodalLoadVector(const Model& model, const DofMap& dofs) {
  return pointLoadVector(model, dofs, model.loads());
}

Eigen::VectorXd loadVector(const Model& model, const DofMap& dofs) {
  Eigen::VectorXd f = nodalLoadVector(model, dofs);
  // Each part adds into its own range of equations, element by element in the model's order.
  forEvenParts(dofs.size(), [&](int first, int end) {
    ReusedForEqual<ElementVector> loadOf;
    for (const auto& e : model.elements()) {
      const auto d = e->dofs();
      const auto owned = [&](const NodeDof& n) {
        const int eq = dofs.equation(n);
        return eq >= first && eq < end;
      };
      if (std::none_of(d.begin(), d.end(), owned)) continue;
      const ElementVector& fe = loadOf.of(*e, [](const Element& x) { return x.load(); });
      if (fe.size() == 0) continue;
      for (int a = 0; a < int(d.size()); ++a)
        if (owned(d[a])) f[dofs.equation(d[a])] += fe[a];
    }
  });
  return f;
}

namespace {

/// An element's own loads (Element::load).
ElementVector ownLoad(int, const Element& e) {
  return e.load();
}

/// The element forces K u - f over every element, f from loadOf(index, element).
template <class LoadOf>
Eigen::VectorXd elementForcesWith(const Model& model, const DofMap& dofs, const Eigen::VectorXd& u,
                                  LoadOf&& loadOf) {
  Eigen::VectorXd r = Eigen::VectorXd::Zero(dofs.size());
  ReusedForEqual<ElementMatrix> stiffnessOf;
  const auto& elements = model.elements();
  for (int i = 0; i < int(elements.size()); ++i) {
    const Element& e = *elements[i];
    const auto d = e.dofs();
    const ElementMatrix& K = stiffnessOf.of(e, [](const Element& x) { return x.stiffness(); });
    const ElementVector fe = endForces(K, loadOf(i, e), gather(e, dofs, u));
    for (int a = 0; a < int(d.size()); ++a) r[dofs.equation(d[a])] += fe[a];
  }
  return r;
}

/// The same at the constrained dofs alone (entry k for equation freeCount + k).
template <class LoadOf>
Eigen::VectorXd constrainedForcesWith(const Model& model, const DofMap& dofs,
                                      const Eigen::VectorXd& u, LoadOf&& loadOf) {
  // The elements touching a constrained dof are found part by part (a pass over every
  // element). Their forces are then added by parts that each own a range of the constrained
  // equations, in the model's order.
  const auto& elements = model.elements();
  const auto constrained = [&](const NodeDof& d) { return dofs.isConstrained(dofs.equation(d)); };
  const std::vector<int> touching =
      pickInParts(int(elements.size()), [&](int i, std::vector<int>& out) {
        const auto d = elements[i]->dofs();
        if (std::any_of(d.begin(), d.end(), constrained)) out.push_back(i);
      });
  const int firstConstrained = dofs.freeCount();
  Eigen::VectorXd r = Eigen::VectorXd::Zero(dofs.constrainedCount());
  const std::vector<int> owners = evenRanges(int(r.size()), partsFor(touching.size()));
  runParts(int(owners.size()) - 1, [&](int part) {
    const auto owned = [&](const NodeDof& d) {
      const int k = dofs.equation(d) - firstConstrained;
      return k >= owners[part] && k < owners[part + 1];
    };
    // The supported elements of a uniform line are equal: their K computed once.
    ReusedForEqual<ElementMatrix> stiffnessOf;
    for (int i : touching) {
      const Element& e = *elements[i];
      const auto d = e.dofs();
      if (std::none_of(d.begin(), d.end(), owned)) continue;
      const ElementMatrix& K = stiffnessOf.of(e, [](const Element& x) { return x.stiffness(); });
      const ElementVector load = loadOf(i, e);
      const ElementVector fe = endForces(K, load, gather(e, dofs, u));
      for (int a = 0; a < int(d.size()); ++a)
        if (owned(d[a])) r[dofs.equation(d[a]) - firstConstrained] += fe[a];
    }
  });
  return r;
}

/// A loading's load on element i: its span load's equivalent nodal loads on a line element,
/// none on the others.
auto loadingLoad(const Loading& loading) {
  return [&loading](int i, const Element& e) {
    const LineElement* line = e.asLineElement();
    return line ? line->loadOf(loading.spanOn(i)) : ElementVector();
  };
}

}  // namespace

Eigen::VectorXd loadVector(const Model& model, const DofMap& dofs, const Loading& loading) {
  Eigen::VectorXd f = pointLoadVector(model, dofs, loading.nodal());
  for (int i : loading.loadedElements()) {
    const Element& e = *model.elements().at(i);
    const ElementVector fe = loadingLoad(loading)(i, e);
    const auto d = e.dofs();
    for (int a = 0; a < int(fe.size()); ++a) f[dofs.equation(d[a])] += fe[a];
  }
  return f;
}

Eigen::VectorXd elementForces(const Model& model, const DofMap& dofs, const Eigen::VectorXd& u) {
  return elementForcesWith(model, dofs, u, ownLoad);
}

Eigen::VectorXd elementForces(const Model& model, const DofMap& dofs, const Eigen::VectorXd& u,
                              const Loading& loading) {
  return elementForcesWith(model, dofs, u, loadingLoad(loading));
}

Eigen::VectorXd constrainedElementForces(const Model& model, const DofMap& dofs,
                                         const Eigen::VectorXd& u) {
  return constrainedForcesWith(model, dofs, u, ownLoad);
}

Eigen::VectorXd constrainedElementForces(const Model& model, const DofMap& dofs,
                                         const Eigen::VectorXd& u, const Loading& loading) {
  return constrainedForcesWith(model, dofs, u, loadingLoad(loading));
}

void dropExactZeros(SparseMatrix& A) {
  A.makeCompressed();
  const int cols = int(A.cols());
  const int* start = A.outerIndexPtr();
  const int* rowOf = A.innerIndexPtr();
  const double* valueOf = A.valuePtr();
  const auto kept = [&](int k, int col) { return valueOf[k] != 0 || rowOf[k] == col; };
  // Count what each column keeps, part by part; then copy it into storage of that size.
  std::vector<int> keptStart(cols + 1, 0);
  const std::vector<int> bounds = balancedColumnRanges(A, partsFor(std::size_t(cols)));
  const int parts = int(bounds.size()) - 1;
  runParts(parts, [&](int part) {
    for (int col = bounds[part]; col < bounds[part + 1]; ++col)
      for (int k = start[col]; k < start[col + 1]; ++k) keptStart[col + 1] += kept(k, col);
  });
  for (int col = 0; col < cols; ++col) keptStart[col + 1] += keptStart[col];
  if (keptStart[cols] == A.nonZeros()) return;
  SparseMatrix B(A.rows(), A.cols());
  B.resizeNonZeros(keptStart[cols]);
  std::copy(keptStart.begin(), keptStart.end(), B.outerIndexPtr());
  runParts(parts, [&](int part) {
    for (int col = bounds[part]; col < bounds[part + 1]; ++col) {
      int next = keptStart[col];
      for (int k = start[col]; k < start[col + 1]; ++k)
        if (kept(k, col)) {
          B.innerIndexPtr()[next] = rowOf[k];
          B.valuePtr()[next++] = valueOf[k];
        }
    }
  });
  A.swap(B);
}

}  // namespace beamrotor

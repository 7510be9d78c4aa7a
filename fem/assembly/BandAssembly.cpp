#include "fem/assembly/BandAssembly.hpp"

#include <algorithm>
#include <array>
#include <stdexcept>

#include "fem/assembly/ParallelParts.hpp"
#include "fem/model/Model.hpp"

namespace beamrotor {

namespace {

/// Widest distance between two free equations of one element, and the entries of the
/// elements' lower triangles over their free dofs, for a range of elements.
struct Reach {
  int halfBandwidth = 0;
  long long elementEntries = 0;
};

Reach reachOf(const Model& model, const DofMap& dofs, int first, int end) {
  Reach r;
  const auto& elements = model.elements();
  for (int i = first; i < end; ++i) {
    int low = dofs.freeCount(), high = -1;
    long long free = 0;
    for (const NodeDof& d : elements[i]->dofs()) {
      const int eq = dofs.equation(d);
      if (!dofs.isFree(eq)) continue;
      low = std::min(low, eq);
      high = std::max(high, eq);
      ++free;
    }
    if (high < 0) continue;
    r.halfBandwidth = std::max(r.halfBandwidth, high - low);
    r.elementEntries += free * (free + 1) / 2;
  }
  return r;
}

}  // namespace

std::optional<int> stiffnessBand(const Model& model, const DofMap& dofs) {
  const int nf = dofs.freeCount();
  if (nf == 0 || !stiffnessSymmetricByConstruction(model)) return std::nullopt;
  const int count = int(model.elements().size());
  const std::vector<int> bounds = evenRanges(count, partsFor(std::size_t(count)));
  std::vector<Reach> parts(bounds.size() - 1);
  runParts(int(parts.size()), [&](int part) {
    parts[part] = reachOf(model, dofs, bounds[part], bounds[part + 1]);
  });
  Reach all;
  for (const Reach& r : parts) {
    all.halfBandwidth = std::max(all.halfBandwidth, r.halfBandwidth);
    all.elementEntries += r.elementEntries;
  }
  const long long bandEntries = (long long)nf * (all.halfBandwidth + 1);
  if (bandEntries > all.elementEntries) return std::nullopt;
  return all.halfBandwidth;
}

SymmetricBand assembleBand(const Model& model, const DofMap& dofs, MatrixKind kind,
                           int halfBandwidth) {
  if (kind == MatrixKind::gyroscopic || kind == MatrixKind::damping)
    throw std::invalid_argument("assembleBand: only stiffness and mass are stored as a band");
  const int nf = dofs.freeCount();
  SymmetricBand A(nf, halfBandwidth);
  const auto fillColumns = [&](int firstColumn, int endColumn) {
    const auto owned = [&](int eq) { return eq >= firstColumn && eq < endColumn; };
    std::array<int, kMaxElementDofs> eq{};
    ReusedForEqual<ElementMatrix> matrixOf;
    for (const auto& e : model.elements()) {
      // Owned equations are free ones: those are numbered first.
      if (!elementEquations(*e, dofs, eq, owned)) continue;
      const int n = int(e->dofs().size());
      const ElementMatrix& m =
          matrixOf.of(*e, [&](const Element& x) { return elementMatrix(x, kind); });
      if (m.size() == 0) continue;
      // Entry (i, j), i >= j, takes the element's (j, i): the upper triangle, the one the
      // sparse path's LDL' reads, so both factorise the same numbers.
      for (int a = 0; a < n; ++a) {
        if (!owned(eq[a])) continue;
        for (int b = 0; b < n; ++b) {
          if (eq[b] < eq[a] || !dofs.isFree(eq[b]) || m(a, b) == 0.0) continue;
          if (eq[b] - eq[a] > halfBandwidth)
            throw std::logic_error("assembleBand: an element reaches outside the band");
          A.lower(eq[b], eq[a]) += m(a, b);
        }
      }
    }
  };
  const std::vector<int> bounds = evenRanges(nf, partsFor(model.elements().size()));
  runParts(int(bounds.size()) - 1, [&](int part) { fillColumns(bounds[part], bounds[part + 1]); });
  return A;
}

}  // namespace beamrotor

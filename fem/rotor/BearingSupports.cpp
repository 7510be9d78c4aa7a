#include "fem/rotor/BearingSupports.hpp"

#include <algorithm>
#include <stdexcept>

#include "fem/model/Model.hpp"
#include "fem/model/RotorElement.hpp"

namespace beamrotor {

const SpeedDependentElement* asBearing(const Element& element) {
  const auto* b = dynamic_cast<const SpeedDependentElement*>(&element);
  return b && b->kind() == "bearing" ? b : nullptr;
}

const SpeedDependentElement* asBearingOnPedestal(const Element& element) {
  const auto* b = dynamic_cast<const SpeedDependentElement*>(&element);
  return b && b->kind() == "bearing-on-pedestal" ? b : nullptr;
}

BearingSupports bearingSupports(const RotorSystem& system, bool pedestals) {
  const DofMap& dofs = system.dofs();
  BearingSupports out{system.stiffness(0), {}, {}};
  for (const auto& e : system.model().elements()) {
    const SpeedDependentElement* b = asBearing(*e);
    const SpeedDependentElement* onPedestal = pedestals ? asBearingOnPedestal(*e) : nullptr;
    const bool pedestal = onPedestal != nullptr;
    if (pedestal) b = onPedestal;
    if (!b) continue;
    const auto d = b->dofs();  // a pedestal's: journal uy, uz, housing uy, uz
    const ElementMatrix k = b->stiffnessAt(0);
    for (int r = 0; r < int(d.size()); ++r) {
      const int row = dofs.equation(d[r]);
      if (!dofs.isFree(row)) continue;
      if (!pedestal) out.equations.push_back(row);
      for (int c = 0; c < int(d.size()); ++c)
        if (const int col = dofs.equation(d[c]); dofs.isFree(col) && k(r, c) != 0)
          out.shaft.coeffRef(row, col) -= k(r, c);
    }
    if (pedestal)
      for (int r = 0; r < 2; ++r)
        if (const int j = dofs.equation(d[r]), h = dofs.equation(d[r + 2]);
            dofs.isFree(j) && dofs.isFree(h))
          out.pedestals.push_back({j, h});
  }
  if (out.equations.empty() && out.pedestals.empty())
    throw std::invalid_argument("the rotor has no bearings (on free dofs) to replace");
  std::sort(out.equations.begin(), out.equations.end());
  out.equations.erase(std::unique(out.equations.begin(), out.equations.end()),
                      out.equations.end());
  return out;
}

std::vector<int> numberingWithout(int n, const std::vector<int>& removed) {
  std::vector<int> index(n, -1);
  for (int i = 0, next = 0; i < n; ++i)
    if (!std::binary_search(removed.begin(), removed.end(), i)) index[i] = next++;
  return index;
}

}  // namespace beamrotor

// One loading of a model's structure other than the loads the model itself carries: a load
// case on the one model. Point loads at nodes and span loads on line elements; solved as one
// more right-hand side of the model's factorised stiffness (fem/static/Static.hpp) and
// recovered along the elements under its own span loads (fem/assembly/Recovery.hpp), so that
// member forces stay exact between the nodes without a model per case.
#pragma once

#include <memory>
#include <utility>
#include <vector>

#include "fem/model/LineElement.hpp"
#include "fem/model/Model.hpp"

namespace beamrotor {

class Loading {
 public:
  Loading() = default;
  /// Point loads, and span loads by element index (several on one element add up).
  Loading(std::vector<NodalLoad> nodal, std::vector<std::pair<int, ElementSpanLoad>> span);

  /// The factored sum of loadings (a combination of load cases): their point loads, scaled,
  /// and their span loads summed when read; the parts are shared, not copied.
  static Loading combination(
      const std::vector<std::pair<std::shared_ptr<const Loading>, double>>& parts);

  const std::vector<NodalLoad>& nodal() const { return nodal_; }
  /// The span load on element `element` (index into Model::elements()); zero when none.
  ElementSpanLoad spanOn(int element) const;
  /// The elements that carry a span load here (from the parts too), ascending, each once.
  std::vector<int> loadedElements() const;

 private:
  std::vector<NodalLoad> nodal_;
  std::vector<std::pair<int, ElementSpanLoad>> span_;  ///< by element, ascending, each once
  std::vector<std::pair<std::shared_ptr<const Loading>, double>> parts_;
};

}  // namespace beamrotor

// A rotor's shaft without its bearings: the stiffness at rest with every Bearing element's own
// stiffness taken out, and the bearings' free lateral equations, so that an analysis can put
// its own supports there (an isotropic stiffness for the critical-speed map, pinned supports
// for the pinned-bearing asymptote and for the static bearing loads).
#pragma once

#include <vector>

#include "fem/model/RotorElement.hpp"
#include "fem/rotor/RotorSystem.hpp"

namespace beamrotor {

/// The element as a bearing: a speed-dependent element of kind "bearing" (elements/Bearing.hpp),
/// or nullptr for any other element.
const SpeedDependentElement* asBearing(const Element& element);

/// The element as a bearing on a pedestal: a speed-dependent element of kind
/// "bearing-on-pedestal" (elements/BearingOnPedestal.hpp), or nullptr for any other element.
const SpeedDependentElement* asBearingOnPedestal(const Element& element);

/// A bearing on a pedestal (kind "bearing-on-pedestal", elements/BearingOnPedestal.hpp): the
/// free equation of the journal and of the housing along one direction.
struct PedestalTie {
  int journal = -1, housing = -1;
};

struct BearingSupports {
  SparseMatrix shaft;          ///< K at rest without the bearings (the system's pattern)
  std::vector<int> equations;  ///< free uy, uz equations of the bearings' nodes, ascending
  /// With pedestals taken out as well: each bearing-on-pedestal's (journal, housing) pairs
  /// along uy and uz; its housing's mass and springs stay in the model.
  std::vector<PedestalTie> pedestals;
};

/// Throws std::invalid_argument when the model has no Bearing element on a free dof (nor,
/// with `pedestals`, a bearing on a pedestal). With `pedestals` the bearings on pedestals are
/// taken out of the shaft as well and listed apart; without, they stay in it.
BearingSupports bearingSupports(const RotorSystem& system, bool pedestals = false);

/// New numbers of the n equations with `removed` (ascending) left out: -1 for a removed one,
/// 0, 1, ... for the others in order.
std::vector<int> numberingWithout(int n, const std::vector<int>& removed);

}  // namespace beamrotor

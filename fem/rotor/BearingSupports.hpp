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

struct BearingSupports {
  SparseMatrix shaft;          ///< K at rest without the bearings (the system's pattern)
  std::vector<int> equations;  ///< free uy, uz equations of the bearings' nodes, ascending
};

/// Throws std::invalid_argument when the model has no Bearing element on a free dof.
BearingSupports bearingSupports(const RotorSystem& system);

/// New numbers of the n equations with `removed` (ascending) left out: -1 for a removed one,
/// 0, 1, ... for the others in order.
std::vector<int> numberingWithout(int n, const std::vector<int>& removed);

}  // namespace beamrotor

// Shear locking: the tip deflection error of a tip-loaded Timoshenko cantilever for the naive
// linear element (full integration), its reduced-integration remedy and the interdependent-
// interpolation element, against slenderness L/h and against the element count.
#pragma once

#include <vector>

namespace beamrotor::verify {

/// Relative tip-deflection errors of the three Timoshenko elements on one mesh.
struct LockingPoint {
  double slenderness = 0;  ///< L / h
  int elements = 0;
  double fullIntegration = 0;     ///< linear element, 2-point shear: locks
  double reducedIntegration = 0;  ///< linear element, 1-point: does not lock
  double interdependent = 0;      ///< exact element: round-off only
};

/// One point per slenderness, each with `elements` elements.
std::vector<LockingPoint> lockingAgainstSlenderness(const std::vector<double>& slenderness,
                                                    int elements);
/// One point per element count at one slenderness.
std::vector<LockingPoint> lockingAgainstElements(double slenderness,
                                                 const std::vector<int>& elementCounts);

}  // namespace beamrotor::verify

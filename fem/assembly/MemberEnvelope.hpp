// The envelope of a member's stress resultants over several static solutions of one structure
// (the combinations of load cases): at each place along the member, the largest and smallest
// value of N, Vy, Vz, T, My, Mz over the solutions and which solution gives it. The places are
// evenly spaced stations plus, on each element, the places of each resultant's largest and
// smallest value over all the solutions (found from each solution's polynomial: at an end or
// where its derivative vanishes), so the envelope's largest and smallest value on every
// element are exact, not sampled, at a cost linear in the solutions.
#pragma once

#include <array>
#include <vector>

#include "fem/assembly/MemberExtrema.hpp"
#include "fem/assembly/Recovery.hpp"
#include "fem/model/Model.hpp"
#include "fem/model/Results.hpp"

namespace beamrotor {

/// The envelope at one place on a member; max and min in the order of kForceComponents,
/// maxBy and minBy the index of the solution that gives each.
struct EnvelopeStation {
  int element = -1;   ///< index into model.elements()
  double s = 0;       ///< fraction of that element's length
  double along = 0;   ///< distance from the member's start (m)
  std::array<double, 6> max{}, min{};
  std::array<int, 6> maxBy{}, minBy{};
};

/// The envelope along member `elements` (line elements from its start to its end) over
/// `solutions` (at least one, all of one structure: LoadedSolution, Recovery.hpp), at
/// intervalsPerElement + 1 even places per element (ends included) and, on each element, the
/// places of each resultant's largest and smallest value over the solutions, in order.
std::vector<EnvelopeStation> memberEnvelope(const std::vector<LoadedSolution>& solutions,
                                            const std::vector<int>& elements,
                                            int intervalsPerElement);

}  // namespace beamrotor

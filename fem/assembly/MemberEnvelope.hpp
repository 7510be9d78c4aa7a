// The envelope of a member's stress resultants over several static solutions of one structure
// (the combinations of load cases): at each place along the member, the largest and smallest
// value of N, Vy, Vz, T, My, Mz over the solutions and which solution gives it. On each element
// a resultant's envelope (the upper one of its largest values, the lower one of its smallest)
// is piecewise one solution's polynomial; the places are evenly spaced stations plus, for
// each resultant and side, every place where the solution on top changes and every stationary
// point of the one on top, so every local extreme of the envelope on every element is exact,
// not sampled (a second peak as well as the largest), and between two places the envelope is
// one polynomial. Solutions whose largest value on an element stays below the smallest value
// of another there are never on top and are not followed, so the cost stays about linear in
// the solutions.
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
/// places where each resultant's upper or lower envelope changes solution or is stationary,
/// in order. With `ranges`, also each solution's range of each resultant along the member
/// (resized to one per solution, kForceComponents order): the values memberForceRanges
/// gives, from the same places on each element, read off the envelope's own pass.
std::vector<EnvelopeStation> memberEnvelope(const std::vector<LoadedSolution>& solutions,
                                            const std::vector<int>& elements,
                                            int intervalsPerElement,
                                            std::vector<std::array<RangeValues, 6>>* ranges = nullptr);

}  // namespace beamrotor

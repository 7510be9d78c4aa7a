// The load combinations that can govern an envelope. Every result of a linear static analysis
// is a linear function of the combination's factors (a combination is the factored sum of its
// load cases), so where one combination's factors are a weighted average of others' (inside
// the convex hull of the factor vectors) it never gives a larger or smaller value than they
// do, anywhere: not a reaction, a resultant at any place along a member, nor a largest
// displacement or stress (convex functions of the factors). The envelope is taken over the
// others: of a grid of factors, its corners.
#pragma once

#include <vector>

#include "problems/run/RunResult.hpp"

namespace beamrotor {

/// One flag per case of `cases` (casesOf order): true for each combination whose factors are
/// an extreme point of all combinations' (extremePoints: the first of equal ones), false for
/// the load cases and the other combinations.
std::vector<bool> combinationsThatCanGovern(const std::vector<CaseOutcome>& cases);

}  // namespace beamrotor

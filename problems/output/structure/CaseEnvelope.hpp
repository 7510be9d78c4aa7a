// The envelope of a static analysis' load combinations, computed once for results.json, the
// summary and the charts: for every reaction component, spring force, member resultant, the largest
// displacement and the largest normal stress, the largest and smallest value over the
// combinations and the combination that gives each (of those that can govern,
// CombinationHull.hpp). From each combination's own extremes
// (StaticExtremes: exact along the members, not sampled).
#pragma once

#include <array>
#include <string>
#include <vector>

#include "fem/model/Model.hpp"
#include "problems/output/structure/StaticExtremes.hpp"
#include "problems/run/RunResult.hpp"

namespace beamrotor {

/// A value over the combinations and the one that gives it: an index into the analysis'
/// cases (casesOf), -1 before any.
struct Governed {
  double value = 0;
  int by = -1;
};

/// The largest and smallest.
struct GovernedRange {
  Governed max, min;
};

struct CaseEnvelope {
  /// One per reaction component, in the order of the solutions' reaction lists.
  std::vector<std::pair<ReactionComponent, GovernedRange>> reactions;
  /// The same for the forces of springs, bearings and contacts (StaticResult::elementForces).
  std::vector<std::pair<ReactionComponent, GovernedRange>> springs;
  /// Per member (Model::members() order), per resultant (kForceComponents order): the largest
  /// of the maxima and the smallest of the minima along it.
  std::vector<std::array<GovernedRange, 6>> members;
  Governed largestDisplacement;  ///< frames
  Governed largestStress;        ///< largest normal stress anywhere
  bool empty() const { return largestStress.by < 0 && largestDisplacement.by < 0; }
};

/// The envelope over the combinations among `cases` (their extremes[i] alongside) that can
/// govern (canGovern[i], combinationsThatCanGovern: the others never exceed them); empty when
/// there are none. Of equal values, the first combination's governs.
CaseEnvelope caseEnvelope(const Model& model, const std::vector<CaseOutcome>& cases,
                          const std::vector<StaticExtremes>& extremes,
                          const std::vector<bool>& canGovern);

/// The combinations (indices into `cases`) a designer checks first, each once, in case order:
/// those that govern the largest displacement, the largest normal stress, and the largest and
/// smallest bending moment in any member (Mz; in a 3d frame also My). What the frame charts of
/// combinations draw (FORMAT.md).
std::vector<int> governingCombinations(const CaseEnvelope& envelope, bool planar);

/// The cases (indices into the analysis' `cases` of count `cases`, in order) that get their
/// own VTK file and samples: every case when `all` (output: all_cases) or when there are no
/// combinations (nothing governs), else the governing combinations alone. The envelope, the
/// summary and results.json cover every case either way.
std::vector<int> writtenCases(const CaseEnvelope& envelope, std::size_t cases, bool planar,
                              bool all);

}  // namespace beamrotor

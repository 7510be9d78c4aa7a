// The extremes of one static solution (the analysis' own, a load case's or a combination's)
// that results.json, the CSV tables and the charts report, computed once per solution: each
// element's exact peaks, each member's resultant ranges and deflection from its chord, and the
// largest displacement (fem/assembly/ElementExtrema.hpp, MemberExtrema.hpp).
#pragma once

#include <array>
#include <optional>
#include <vector>

#include "fem/assembly/ElementExtrema.hpp"
#include "fem/assembly/MemberExtrema.hpp"
#include "fem/assembly/Recovery.hpp"
#include "problems/output/structure/LineSampling.hpp"
#include "problems/run/RunResult.hpp"

namespace beamrotor {

struct StaticExtremes {
  /// Every line element's, in order; of a load case or combination only those of the elements
  /// that can hold its largest of a kind (peaksThatCanGovern: the largest of each kind is the
  /// same), a written case's every element's in PreparedCase::peaks.
  std::vector<ElementPeaks> peaks;
  std::vector<std::array<ComponentRange, 6>> ranges;  ///< per member, Model::members() order
  std::vector<MemberValue> chordDeflections;  ///< per member; empty when not reported
  MemberValue largestDisplacement;  ///< anywhere (largestDisplacement); frames only
};

/// Which element peaks staticExtremes keeps: every line element's, or only those of the
/// elements that can hold the largest of a kind (peaksThatCanGovern).
enum class PeaksKept { everyElement, canGovern };

/// The extremes of `solution`; the member parts and the largest displacement left empty for
/// a model without members (a line), the chord deflections without `chordDeflections`.
StaticExtremes staticExtremes(const LoadedSolution& solution,
                              PeaksKept kept = PeaksKept::everyElement,
                              bool chordDeflections = true);

/// The extremes of a static analysis: its own solution's and each of its load cases' and
/// combinations' (casesOf order; their peaks PeaksKept::canGovern, their chord deflections
/// only where reported, caseChordDeflections). Empty for the other kinds of analysis.
struct AnalysisExtremes {
  std::optional<StaticExtremes> own;
  std::vector<StaticExtremes> cases;
};

/// The extremes of each analysis of a run (run.analyses order).
std::vector<AnalysisExtremes> runExtremes(const RunResult& run);

}  // namespace beamrotor

// The extremes of one static solution (the analysis' own, a load case's or a combination's)
// that results.json, the CSV tables and the charts report, computed once per solution: each
// element's exact peaks, each member's resultant ranges and deflection from its chord, and the
// largest displacement (fem/assembly/ElementExtrema.hpp, MemberExtrema.hpp).
#pragma once

#include <array>
#include <optional>
#include <vector>

#include "fem/assembly/ElementExtrema.hpp"
#include "fem/assembly/MemberEnvelope.hpp"
#include "fem/assembly/MemberExtrema.hpp"
#include "fem/assembly/Recovery.hpp"
#include "fem/assembly/SolutionPolynomials.hpp"
#include "problems/output/structure/LineSampling.hpp"
#include "problems/run/RunResult.hpp"

namespace beamrotor {

struct StaticExtremes {
  /// Every line element's, in order; of a load case or combination only those of the elements
  /// that can hold its largest of a kind (peaksThatCanGovern: the largest of each kind is the
  /// same), a written case's every element's in PreparedCase::peaks.
  std::vector<ElementPeaks> peaks;
  /// Per member, Model::members() order, with their places; empty where only the values are
  /// kept (RangesKept::values).
  std::vector<std::array<ComponentRange, 6>> ranges;
  /// Per member, the values alone where `ranges` is not kept (96 bytes a member against 672:
  /// 200 combinations of a 10^4-member frame held 1.2 GB of places nothing reported).
  std::vector<std::array<RangeValues, 6>> rangeValues;
  std::vector<MemberValue> chordDeflections;  ///< per member; empty when not reported
  MemberValue largestDisplacement;  ///< anywhere (largestDisplacement); frames only
};

/// Which element peaks staticExtremes keeps: every line element's, or only those of the
/// elements that can hold the largest of a kind (peaksThatCanGovern).
enum class PeaksKept { everyElement, canGovern };

/// Whether staticExtremes keeps each member range's place (element, position, point) or only
/// its values (the envelope over the combinations reads no more), or leaves the values to the
/// envelope along the members (byEnvelope: rangeValues one per member, filled by
/// memberEnvelope's pass over each element's combinations, which ranges them anyway), or keeps
/// none (a combination that cannot govern the envelope, where no member detail is reported).
enum class RangesKept { withPlaces, values, byEnvelope, none };

/// The extremes of `solution`; the member parts and the largest displacement left empty for
/// a model without members (a line), the chord deflections without `chordDeflections`.
StaticExtremes staticExtremes(const LoadedSolution& solution,
                              PeaksKept kept = PeaksKept::everyElement,
                              bool chordDeflections = true,
                              RangesKept ranges = RangesKept::withPlaces);

/// How many members x holds ranges of (with their places or as values).
std::size_t rangedMembers(const StaticExtremes& x);

/// Member m's range of resultant f (kForceComponents order), its values.
RangeValues rangeValuesOf(const StaticExtremes& x, std::size_t m, std::size_t f);

/// The extremes of load case or combination c of the model (a combination's polynomials summed
/// into `summed`, storage reused from one call to the next, where its member ranges or chord
/// deflections read every element), as runExtremes gives them: its peaks that can govern, its
/// chord deflections where `chordDeflections`.
StaticExtremes caseExtremes(const Model& model, const CaseOutcome& c, SolutionPolynomials& summed,
                            bool chordDeflections, RangesKept ranges);

/// The extremes of a static analysis: its own solution's and each of its load cases' and
/// combinations' (casesOf order; their peaks PeaksKept::canGovern, their chord deflections
/// and their member ranges' places only where reported, caseChordDeflections; the cases
/// written get theirs with places in PreparedCase). Empty for the other kinds of analysis.
struct AnalysisExtremes {
  std::optional<StaticExtremes> own;
  std::vector<StaticExtremes> cases;
  /// Per case: whether it is a combination that can govern the envelope
  /// (combinationsThatCanGovern); the envelope is taken over those alone.
  std::vector<bool> canGovern;
  /// With MemberEnvelopes::computed and combinations on a frame: the envelope along each
  /// member over the combinations that can govern (memberEnvelope, Model::members() order;
  /// each station's maxBy and minBy index the analysis' combinations, in order).
  std::vector<std::vector<EnvelopeStation>> memberEnvelopes;
};

/// Whether runExtremes also computes the envelope along the members (what the results
/// directory writes): then each combination's member ranges, where only their values are
/// kept, come from the same pass over each element's combinations instead of a second one.
enum class MemberEnvelopes { skipped, computed };

/// The extremes of each analysis of a run (run.analyses order).
std::vector<AnalysisExtremes> runExtremes(const RunResult& run,
                                          MemberEnvelopes envelopes = MemberEnvelopes::skipped);

}  // namespace beamrotor

// The extremes of a static solution, computed once (see StaticExtremes.hpp).
#include "problems/output/structure/StaticExtremes.hpp"

#include <algorithm>

#include "fem/assembly/ParallelParts.hpp"
#include "fem/assembly/SolutionPolynomials.hpp"
#include "problems/output/structure/CombinationHull.hpp"
#include "problems/output/structure/MemberOutput.hpp"

namespace beamrotor {

StaticExtremes staticExtremes(const LoadedSolution& solution, PeaksKept kept,
                              bool chordDeflections, RangesKept ranges) {
  StaticExtremes out;
  out.peaks = kept == PeaksKept::everyElement ? elementPeaks(solution) : peaksThatCanGovern(solution);
  // Reserved: 200 combinations of a 10^4-member frame hold 200 of these.
  const std::size_t members = solution.model->members().size();
  if (ranges == RangesKept::withPlaces)
    out.ranges.reserve(members);
  else if (ranges == RangesKept::values)
    out.rangeValues.reserve(members);
  else if (ranges == RangesKept::byEnvelope)
    out.rangeValues.resize(members);  // filled by the envelope's pass (runExtremes)
  if (chordDeflections) out.chordDeflections.reserve(members);
  for (const auto& [name, elements] : solution.model->members()) {
    if (chordDeflections) out.chordDeflections.push_back(largestChordDeflection(solution, elements));
    if (ranges == RangesKept::byEnvelope || ranges == RangesKept::none) continue;
    const std::array<ComponentRange, 6> r = memberForceRanges(solution, elements);
    if (ranges == RangesKept::withPlaces) {
      out.ranges.push_back(r);
    } else {
      std::array<RangeValues, 6>& values = out.rangeValues.emplace_back();
      for (std::size_t f = 0; f < r.size(); ++f) values[f] = {r[f].max.value, r[f].min.value};
    }
  }
  // A line's largest displacement is read from its fields; a frame's is reported on its own.
  if (!solution.model->members().empty()) out.largestDisplacement = largestDisplacement(solution);
  return out;
}

std::size_t rangedMembers(const StaticExtremes& x) {
  return std::max(x.ranges.size(), x.rangeValues.size());
}

RangeValues rangeValuesOf(const StaticExtremes& x, std::size_t m, std::size_t f) {
  if (x.ranges.empty()) return x.rangeValues.at(m)[f];
  const ComponentRange& r = x.ranges.at(m)[f];
  return {r.max.value, r.min.value};
}

StaticExtremes caseExtremes(const Model& model, const CaseOutcome& c, SolutionPolynomials& summed,
                            bool chordDeflections, RangesKept ranges) {
  LoadedSolution solution = c.on(model);
  // Summed once where every element is read more than once (the member ranges, the chord
  // deflections); otherwise read through the cases' bounds and summed only where needed.
  const bool everyElement = chordDeflections || ranges == RangesKept::withPlaces ||
                            ranges == RangesKept::values;
  if (c.combination && c.polynomials && everyElement) {
    c.polynomials->sumInto(summed);
    solution.polynomials = &summed;
  }
  return staticExtremes(solution, PeaksKept::canGovern, chordDeflections, ranges);
}

namespace {

/// The envelope along each member of `model` over the combinations among `cases` that can
/// govern (x.canGovern) into x.memberEnvelopes, each station naming its combinations by their
/// index among all the combinations; where `fillRanges`, those combinations' member ranges
/// (left to it, RangesKept::byEnvelope) from the same pass. Each member is computed whole by
/// one part (its own range of members), so the results are the same to the bit however many
/// parts run.
void memberEnvelopes(const Model& model, const std::vector<CaseOutcome>& cases,
                     AnalysisExtremes& x, bool fillRanges) {
  std::vector<LoadedSolution> combinations;
  std::vector<std::size_t> caseOf;  // each one's index into cases
  std::vector<int> named;           // each one's index among all the combinations
  int combination = 0;
  for (std::size_t k = 0; k < cases.size(); ++k) {
    if (!cases[k].combination) continue;
    if (x.canGovern.at(k)) {
      combinations.push_back(cases[k].on(model));
      caseOf.push_back(k);
      named.push_back(combination);
    }
    ++combination;
  }
  if (combinations.empty()) return;
  const auto& members = model.members();
  x.memberEnvelopes.resize(members.size());
  const std::vector<int> bounds = evenRanges(
      int(members.size()), partsFor(combinations.size() * model.elements().size()));
  runParts(int(bounds.size()) - 1, [&](int part) {
    std::vector<std::array<RangeValues, 6>> ranges;  // the member's, one per combination
    for (int m = bounds[part]; m < bounds[part + 1]; ++m) {
      x.memberEnvelopes[m] = memberEnvelope(combinations, members[m].second, kIntervalsPerElement,
                                            fillRanges ? &ranges : nullptr);
      for (EnvelopeStation& station : x.memberEnvelopes[m])
        for (std::size_t f = 0; f < kForceComponents.size(); ++f) {
          station.maxBy[f] = named[std::size_t(station.maxBy[f])];
          station.minBy[f] = named[std::size_t(station.minBy[f])];
        }
      if (fillRanges)
        for (std::size_t k = 0; k < combinations.size(); ++k)
          x.cases[caseOf[k]].rangeValues[m] = ranges[k];
    }
  });
}

}  // namespace

std::vector<AnalysisExtremes> runExtremes(const RunResult& run, MemberEnvelopes envelopes) {
  std::vector<AnalysisExtremes> out(run.analyses.size());
  for (std::size_t i = 0; i < run.analyses.size(); ++i) {
    const AnalysisOutcome& a = run.analyses[i];
    if (const StaticResult* s = staticsOf(a))
      out[i].own = staticExtremes({*run.model, s->displacement});
    const std::vector<CaseOutcome>& cases = casesOf(a);
    const bool chords = caseChordDeflections(*run.model, cases.size());
    // The member ranges' places are reported with the chord deflections (results.json's
    // member detail, the summary's cases in full); elsewhere the envelope reads their values,
    // and a combination's come from the envelope's own pass when it is computed.
    // A combination that cannot govern keeps no member ranges where none are reported.
    const bool envelope = envelopes == MemberEnvelopes::computed;
    out[i].canGovern = combinationsThatCanGovern(cases);
    const auto kept = [&](std::size_t k) {
      if (chords) return RangesKept::withPlaces;
      if (!cases[k].combination) return RangesKept::values;
      if (!out[i].canGovern[k]) return RangesKept::none;
      return envelope ? RangesKept::byEnvelope : RangesKept::values;
    };
    // Each case's extremes are computed whole by one part (its own range of cases, in order),
    // so they are the same to the bit however many parts run.
    out[i].cases.resize(cases.size());
    const std::size_t work = cases.size() * run.model->elements().size();
    const std::vector<int> bounds = evenRanges(int(cases.size()), partsFor(work));
    runParts(int(bounds.size()) - 1, [&](int part) {
      SolutionPolynomials summed;  // one combination's at a time, its storage reused
      for (int k = bounds[part]; k < bounds[part + 1]; ++k)
        out[i].cases[k] = caseExtremes(*run.model, cases[k], summed, chords, kept(std::size_t(k)));
    });
    if (envelope) memberEnvelopes(*run.model, cases, out[i], !chords);
  }
  return out;
}

}  // namespace beamrotor

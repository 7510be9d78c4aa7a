// The extremes of a static solution, computed once (see StaticExtremes.hpp).
#include "problems/output/structure/StaticExtremes.hpp"

#include "fem/assembly/ParallelParts.hpp"
#include "fem/assembly/SolutionPolynomials.hpp"
#include "problems/output/structure/MemberOutput.hpp"

namespace beamrotor {

StaticExtremes staticExtremes(const LoadedSolution& solution, PeaksKept kept,
                              bool chordDeflections) {
  StaticExtremes out;
  out.peaks = kept == PeaksKept::everyElement ? elementPeaks(solution) : peaksThatCanGovern(solution);
  for (const auto& [name, elements] : solution.model->members()) {
    out.ranges.push_back(memberForceRanges(solution, elements));
    if (chordDeflections) out.chordDeflections.push_back(largestChordDeflection(solution, elements));
  }
  // A line's largest displacement is read from its fields; a frame's is reported on its own.
  if (!solution.model->members().empty()) out.largestDisplacement = largestDisplacement(solution);
  return out;
}

std::vector<AnalysisExtremes> runExtremes(const RunResult& run) {
  std::vector<AnalysisExtremes> out(run.analyses.size());
  for (std::size_t i = 0; i < run.analyses.size(); ++i) {
    const AnalysisOutcome& a = run.analyses[i];
    if (const StaticResult* s = staticsOf(a))
      out[i].own = staticExtremes({*run.model, s->displacement});
    const std::vector<CaseOutcome>& cases = casesOf(a);
    const bool chords = caseChordDeflections(*run.model, cases.size());
    // Each case's extremes are computed whole by one part (its own range of cases, in order),
    // so they are the same to the bit however many parts run.
    out[i].cases.resize(cases.size());
    const std::size_t work = cases.size() * run.model->elements().size();
    const std::vector<int> bounds = evenRanges(int(cases.size()), partsFor(work));
    runParts(int(bounds.size()) - 1, [&](int part) {
      SolutionPolynomials summed;  // one combination's at a time, its storage reused
      for (int k = bounds[part]; k < bounds[part + 1]; ++k) {
        const CaseOutcome& c = cases[k];
        LoadedSolution solution = c.on(*run.model);
        if (c.combination && c.polynomials) {
          c.polynomials->sumInto(summed);
          solution.polynomials = &summed;
        }
        out[i].cases[k] = staticExtremes(solution, PeaksKept::canGovern, chords);
      }
    });
  }
  return out;
}

}  // namespace beamrotor

// The extremes of a static solution, computed once (see StaticExtremes.hpp).
#include "problems/output/structure/StaticExtremes.hpp"

namespace beamrotor {

StaticExtremes staticExtremes(const LoadedSolution& solution) {
  StaticExtremes out;
  out.peaks = elementPeaks(solution);
  for (const auto& [name, elements] : solution.model->members()) {
    out.ranges.push_back(memberForceRanges(solution, elements));
    out.chordDeflections.push_back(largestChordDeflection(solution, elements));
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
    for (const CaseOutcome& c : casesOf(a))
      out[i].cases.push_back(staticExtremes(c.on(*run.model)));
  }
  return out;
}

}  // namespace beamrotor

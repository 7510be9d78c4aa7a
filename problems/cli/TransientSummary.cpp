#include "problems/cli/TransientSummary.hpp"

#include <algorithm>

#include "problems/cli/Summary.hpp"

namespace beamrotor::cli {

namespace {

const TransientOutcome* transientOf(const RunResult& run) {
  for (const AnalysisOutcome& a : run.analyses)
    if (const TransientOutcome* t = resultOf<TransientOutcome>(a)) return t;
  return nullptr;
}

}  // namespace

void printTransient(std::ostream& out, const AnalysisOutcome& a) {
  const TransientOutcome& t = *resultOf<TransientOutcome>(a);
  const TransientResult& r = t.result;
  out << "transient analysis '" << a.name << "' (" << r.scheme
      << ", dt = " << formatValue(r.timeStep) << " s, " << r.steps
      << " steps to t = " << formatValue(r.steps * r.timeStep) << " s";
  if (r.stability.omegaMax > 0)
    out << ", dt_crit = " << formatValue(r.stability.dtCritical) << " s";
  out << ")\n";
  for (const NamedHistory& h : t.histories)
    out << "    " << padded(h.name, 18)
        << padded("max |.| " + formatValue(h.maxAbs()) + " " + h.unit, 28) << "range ["
        << formatValue(h.min()) << ", " << formatValue(h.max()) << "]\n";
  if (!r.impacts.empty())
    out << "    " << r.impacts.size()
        << " impact(s) on stops, the first at t = " << formatValue(r.impacts.front().time)
        << " s\n";
  for (const std::string& w : r.warnings) out << "  warning: " << w << "\n";
}

void printTransientSweep(std::ostream& out, const SweepResult& sweep) {
  const TransientOutcome* first = sweep.runs.empty() ? nullptr : transientOf(sweep.runs.front());
  if (!first || first->histories.empty()) return;
  constexpr std::size_t kColumn = 18;
  out << "  " << padded(sweep.parameter, kColumn);
  for (const NamedHistory& h : first->histories) out << padded(h.name + "_max", kColumn);
  out << "\n";
  for (std::size_t k = 0; k < sweep.runs.size(); ++k) {
    out << "  " << padded(formatValue(sweep.values[k]), kColumn);
    if (const TransientOutcome* t = transientOf(sweep.runs[k]))
      for (const NamedHistory& h : t->histories) out << padded(formatValue(h.maxAbs()), kColumn);
    out << "\n";
  }
  out << "  (largest |value| of each history over the run)\n";
}

}  // namespace beamrotor::cli

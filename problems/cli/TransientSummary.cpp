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

void printTransient(std::ostream& out, const AnalysisOutcome& a, const OutputUnits& units) {
  const TransientOutcome& t = *resultOf<TransientOutcome>(a);
  const TransientResult& r = t.result;
  const auto time = [&](double seconds) { return valueText(seconds, "s", units); };
  out << "transient analysis '" << a.name << "' (" << r.scheme << ", dt = " << time(r.timeStep)
      << ", " << r.steps << " steps to t = " << time(r.steps * r.timeStep);
  if (r.stability.omegaMax > 0) out << ", dt_crit = " << time(r.stability.dtCritical);
  out << ")\n";
  for (const NamedHistory& h : t.histories) {
    // A history's unit is the deck's free text: converted where it names a unit of a set
    // quantity, else shown as written.
    const OutputUnits::Shown shown = units.valueIn(h.unit, {1, h.unit});
    out << "    " << padded(h.name, 18)
        << padded("max |.| " + formatValue(h.maxAbs() * shown.factor) + " " + shown.unit, 28)
        << "range [" << formatValue(h.min() * shown.factor) << ", "
        << formatValue(h.max() * shown.factor) << "]\n";
  }
  if (!r.impacts.empty())
    out << "    " << r.impacts.size()
        << " impact(s) on stops, the first at t = " << time(r.impacts.front().time) << "\n";
  for (const std::string& w : r.warnings) out << "  warning: " << w << "\n";
}

void printTransientSweep(std::ostream& out, const SweepResult& sweep, const OutputUnits& units) {
  const TransientOutcome* first = sweep.runs.empty() ? nullptr : transientOf(sweep.runs.front());
  if (!first || first->histories.empty()) return;
  constexpr std::size_t kColumn = 18;
  // "name unit": the column's unit, the user's where they set its quantity.
  const auto header = [&](const std::string& name, const std::string& unit) {
    const std::string shown = units.valueIn(unit, {1, unit}).unit;
    return shown.empty() ? name : name + " " + shown;
  };
  out << "  " << padded(header(sweep.parameter, sweep.unit), kColumn);
  for (const NamedHistory& h : first->histories)
    out << padded(header(h.name + "_max", h.unit), kColumn);
  out << "\n";
  const double swept = units.valueIn(sweep.unit, {1, sweep.unit}).factor;
  for (std::size_t k = 0; k < sweep.runs.size(); ++k) {
    out << "  " << padded(formatValue(sweep.values[k] * swept), kColumn);
    if (const TransientOutcome* t = transientOf(sweep.runs[k]))
      for (const NamedHistory& h : t->histories)
        out << padded(formatValue(h.maxAbs() * units.valueIn(h.unit, {1, h.unit}).factor),
                      kColumn);
    out << "\n";
  }
  out << "  (largest |value| of each history over the run)\n";
}

}  // namespace beamrotor::cli

#include "problems/cli/MovingSummary.hpp"

#include "problems/cli/Summary.hpp"

namespace beamrotor::cli {

void printMovingLoad(std::ostream& out, const AnalysisOutcome& a, const MovingLoadOutcome& m) {
  out << "moving-load analysis '" << a.name << "': " << m.train.size() << " wheel(s) along "
      << formatValue(m.length) << " m of path, direction [" << formatValue(m.direction[0]) << ", "
      << formatValue(m.direction[1]) << ", " << formatValue(m.direction[2]) << "]\n";
  for (const MovingQuantity& q : m.quantities)
    out << "    " << q.text << ": max " << formatValue(q.envelope.max.value) << " " << q.valueUnit
        << " (first wheel at " << formatValue(q.envelope.max.lead) << " m), min "
        << formatValue(q.envelope.min.value) << " " << q.valueUnit << " (first wheel at "
        << formatValue(q.envelope.min.lead) << " m)\n";
}

}  // namespace beamrotor::cli

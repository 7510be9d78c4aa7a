#include "problems/cli/MovingSummary.hpp"

#include "problems/cli/Summary.hpp"

namespace beamrotor::cli {

void printMovingLoad(std::ostream& out, const AnalysisOutcome& a, const MovingLoadOutcome& m,
                     const OutputUnits& units) {
  out << "moving-load analysis '" << a.name << "': " << m.train.size() << " wheel(s) along "
      << valueText(m.length, "m", units) << " of path, direction ["
      << formatValue(m.direction[0]) << ", " << formatValue(m.direction[1]) << ", "
      << formatValue(m.direction[2]) << "]"
      << (m.deckLoads ? ", with the deck's own loads" : ", the train alone (deck_loads: false)")
      << "\n";
  for (const MovingQuantity& q : m.quantities) {
    out << "    " << q.text << ": max " << valueText(q.envelope.max.value, q.valueUnit, units)
        << " (first wheel at " << valueText(q.envelope.max.lead, "m", units) << "), min "
        << valueText(q.envelope.min.value, q.valueUnit, units) << " (first wheel at "
        << valueText(q.envelope.min.lead, "m", units) << ")";
    if (m.deckLoads && q.deckValue != 0)
      out << "; deck loads alone " << valueText(q.deckValue, q.valueUnit, units);
    out << "\n";
  }
}

}  // namespace beamrotor::cli

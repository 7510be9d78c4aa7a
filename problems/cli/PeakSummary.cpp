#include "problems/cli/PeakSummary.hpp"

#include "problems/cli/Summary.hpp"
#include "problems/deck/ShownFieldUnit.hpp"
#include "problems/deck/parse/DeckSource.hpp"
#include "problems/deck/parse/Field.hpp"
#include "problems/deck/study/ReadSweepRefinement.hpp"
#include "problems/run/SweepRefinement.hpp"

namespace beamrotor::cli {

void printSweepPeaks(std::ostream& out, const Study& study, const std::string& deckPath,
                     const OutputUnits& units) {
  if (!study.sweep || !study.deck.sweep || study.deck.sweep->place.line == 0) return;
  const auto refine = readSweepRefinement(loadDeckFile(deckPath), study.deck);
  if (!refine || refine->parameter != study.sweep->parameter) return;
  const auto peaks = sweepPeaks(sweepSamples(*study.sweep, *refine));
  out << "peaks of " << refine->quantity.text << " (" << refine->analysis << "), "
      << study.sweep->values.size() << " values, bracketed to " << formatNumber(refine->tolerance)
      << " of " << refine->parameter << ":";
  if (peaks.empty()) out << " none inside the range";
  // Each peak's value in the user's unit of the quantity where set, else in its own.
  const OutputUnits::Shown shown = shownField(units, checkQuantityUnit(refine->quantity.text));
  for (const auto& [value, result] : peaks) {
    out << (&value == &peaks.front().first ? " " : ", ") << refine->parameter << " = "
        << valueText(value, study.sweep->unit, units) << " ("
        << formatNumber(result * shown.factor);
    if (!shown.unit.empty()) out << " " << shown.unit;
    out << ")";
  }
  out << "\n";
}

}  // namespace beamrotor::cli

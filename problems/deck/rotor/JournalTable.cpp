#include "problems/deck/rotor/JournalTable.hpp"

#include <numbers>
#include <stdexcept>

#include "elements/ConcentricJournal.hpp"
#include "elements/PlainJournalBearing.hpp"
#include "problems/deck/parse/Field.hpp"

namespace beamrotor {

void fillJournalTable(DeckBearing& b) {
  const PlainJournal& j = *b.journal;
  b.table.clear();
  if (j.load == 0) {  // an unloaded journal runs centred
    for (double w : b.speeds) b.table.push_back(concentricJournalCoefficients(j, w));
    return;
  }
  // Below 1 % of the clearance the film is thinner than any real surface finish allows (the
  // journal runs on the bearing), and the linear coefficients grow without bound.
  constexpr double kThinnestFilm = 0.01;
  const double slowest = eccentricityRatio(j, b.speeds.front());
  if (slowest > 1 - kThinnestFilm)
    throw std::invalid_argument(
        "at " + formatNumber(b.speeds.front() * 30 / std::numbers::pi) + " rpm the film carries the load (" +
        formatNumber(j.load) + " N) only at eccentricity " + formatNumber(slowest) +
        " (thinner than 1 % of c: the journal touches the bearing); raise from_rpm, mu or L, or "
        "check load and c");
  for (double w : b.speeds) b.table.push_back(shortBearingCoefficients(j, w));
}

}  // namespace beamrotor

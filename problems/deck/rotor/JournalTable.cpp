#include "problems/deck/rotor/JournalTable.hpp"

#include <numbers>
#include <stdexcept>
#include <string>

#include "elements/ConcentricJournal.hpp"
#include "elements/PlainJournalBearing.hpp"
#include "elements/TiltingPadBearing.hpp"
#include "problems/deck/parse/Field.hpp"

namespace beamrotor {

namespace {

/// The operating points of a loaded journal at each table speed, by its model.
void fillLoadedJournalPoints(DeckBearing& b) {
  const PlainJournal& j = *b.journal;
  // Below 1 % of the clearance the film is thinner than any real surface finish allows (the
  // journal runs on the bearing), and the linear coefficients grow without bound.
  constexpr double kThinnestFilm = 0.01;
  static_assert(kFiniteMaxEccentricity == 1 - kThinnestFilm);
  const std::string slowestRpm = formatNumber(b.speeds.front() * 30 / std::numbers::pi);
  auto touches = [&](const std::string& eccentricity) {
    return std::invalid_argument(
        "at " + slowestRpm + " rpm the film carries the load (" + formatNumber(j.load) +
        " N) only at eccentricity " + eccentricity +
        " (thinner than 1 % of c: the journal touches the bearing); raise from_rpm, mu or L, or "
        "check load and c");
  };
  if (b.tiltingPads) {
    // The pads' equilibrium and synchronous coefficients once per table speed.
    for (double w : b.speeds) {
      try {
        // Each speed's Newton starts from the last speed's equilibrium.
        TiltingPadPoint p = tiltingPadPoint(j, *b.tiltingPads, w, b.journalGrid,
                                            b.padPoints.empty() ? nullptr : &b.padPoints.back());
        b.journalPoints.push_back({p.eccentricity, p.attitude, p.synchronous});
        b.padPoints.push_back(std::move(p));
      } catch (const std::invalid_argument& e) {
        throw std::invalid_argument("at " + formatNumber(w * 30 / std::numbers::pi) +
                                    " rpm: " + e.what() + "; raise from_rpm, mu or L, or check "
                                    "load and c");
      }
    }
  } else if (b.journalModel == DeckBearing::JournalModel::shortBearing) {
    const double slowest = eccentricityRatio(j, b.speeds.front());
    if (slowest > 1 - kThinnestFilm) throw touches(formatNumber(slowest));
    for (double w : b.speeds) {
      const double eps = eccentricityRatio(j, w);
      b.journalPoints.push_back({eps, attitudeAngle(eps), shortBearingCoefficients(j, w)});
    }
  } else {
    // The film is solved once per table speed (the table is the cache the runs read).
    for (double w : b.speeds) {
      try {
        b.journalPoints.push_back(finiteJournalPoint(j, w, b.journalGrid));
      } catch (const std::invalid_argument&) {
        if (b.journalPoints.empty()) throw touches("above " + formatNumber(kFiniteMaxEccentricity));
        throw;
      }
    }
  }
}

}  // namespace

void fillJournalTable(DeckBearing& b) {
  const PlainJournal& j = *b.journal;
  b.table.clear();
  b.journalPoints.clear();
  b.padPoints.clear();
  if (j.load == 0) {  // an unloaded journal runs centred
    if (b.journalModel != DeckBearing::JournalModel::shortBearing)
      throw std::invalid_argument(
          "an unloaded journal (load: 0) runs centred with the short-bearing coefficients at "
          "zero eccentricity; the finite film is solved for a load only (give the load, or "
          "model: short where L/D <= 1)");
    for (double w : b.speeds)
      b.journalPoints.push_back({0.0, attitudeAngle(0.0), concentricJournalCoefficients(j, w)});
  } else {
    fillLoadedJournalPoints(b);
  }
  for (const JournalOperatingPoint& p : b.journalPoints) b.table.push_back(p.coefficients);
}

}  // namespace beamrotor

// A moving-load analysis, solved: each quantity's influence line along the path (exact
// piecewise cubics) and its envelope under the train, with the train's governing positions.
#pragma once

#include <array>
#include <string>
#include <vector>

#include "fem/static/FieldEnvelopes.hpp"
#include "fem/static/InfluenceLines.hpp"
#include "fem/static/TrainEnvelope.hpp"

namespace beamrotor {

/// One quantity of a moving-load analysis.
struct MovingQuantity {
  std::string text;   ///< as the deck names it, e.g. "reaction B uy"
  std::string unit;   ///< its SI unit per unit load ("N" per N: "1"; "m" per N: "m/N") for tables
  std::string valueUnit;  ///< the unit of its values under the train: "N", "N m", "m" or "rad"
  InfluenceLine line;     ///< for a unit load along the direction (value per N)
  /// The value under the deck's own loads alone (0 when they are left out).
  double deckValue = 0;
  /// The deck's loads plus the train: the train's extremes and where, with deckValue added.
  TrainEnvelope envelope;
  /// The displacements (m, rad) under the deck's loads plus the train at the governing
  /// positions of the largest and the smallest value.
  NodalField shapeAtMax, shapeAtMin;
};

struct MovingLoadOutcome {
  std::array<double, 3> direction{0, -1, 0};
  std::vector<TrainLoad> train;
  double length = 0;  ///< of the path (m)
  bool deckLoads = true;  ///< the deck's own loads are in the envelopes (deck_loads:)
  /// Every node's displacements and every line element's end resultants, enveloped the same
  /// way (the deck's loads included when deckLoads); empty unless `field_envelopes: true`.
  FieldEnvelopes fields;
  std::vector<MovingQuantity> quantities;
  /// The envelope of quantity `text`; throws std::invalid_argument when it is not one of them.
  const MovingQuantity& quantity(const std::string& text) const;
};

}  // namespace beamrotor

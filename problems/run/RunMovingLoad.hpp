// Running a moving-load analysis (MovingLoadSpec): the path's elements in order, each quantity
// as a function of a static solution, their influence lines from one factorisation of K
// (fem/static/InfluenceLines.hpp) and their envelopes under the train (TrainEnvelope.hpp).
#pragma once

#include "fem/model/Model.hpp"
#include "problems/deck/Deck.hpp"
#include "problems/run/MovingLoadOutcome.hpp"

namespace beamrotor {

/// Solves `spec` on `model` (the deck's). Throws std::invalid_argument for a path the
/// influence lines cannot be exact on (a hinge or a Timoshenko element along it).
MovingLoadOutcome runMovingLoad(const MovingLoadSpec& spec, const Model& model);

/// Where `resultant COMP at POINT` is read: the line element starting at the point's node (its
/// start, end 0), else the one ending there (end 1); throws std::invalid_argument when no beam
/// meets the point.
struct ResultantPlace {
  int element = -1;
  int end = 0;
};
ResultantPlace resultantPlace(const Model& model, const std::string& point);

}  // namespace beamrotor

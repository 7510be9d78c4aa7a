// `accuracy: 1e-4` in a deck: the relative accuracy wanted on its checked quantities, which
// lets the solver pick the cheapest adequate model (problems/run/AdequateModel.hpp).
#pragma once

#include "problems/deck/parse/DeckError.hpp"

namespace beamrotor {

struct DeckAccuracy {
  double target = 0;  ///< relative, 0 < target < 1
  DeckPlace place;
};

}  // namespace beamrotor

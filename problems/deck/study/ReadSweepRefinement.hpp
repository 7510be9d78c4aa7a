// The `refine:` entry of a deck's sweep: refine the sweep where a result changes fast and
// around its peaks (run/SweepRefinement does it). Read from the deck's YAML apart from the
// rest of the sweep, as the sweep's values may come from the command line.
#pragma once

#include <optional>
#include <string>

#include "problems/deck/Deck.hpp"
#include "problems/deck/parse/DeckSource.hpp"
#include "problems/deck/Quantity.hpp"

namespace beamrotor {

struct DeckSweepRefinement {
  std::string parameter;  ///< the deck's swept parameter, which it refines
  Quantity quantity;      ///< what to follow, a check quantity
  std::string analysis;   ///< the analysis it reads
  double tolerance = 0;   ///< peaks bracketed to this fraction of the parameter's value
  int runs = 0;           ///< at most this many values in all
  DeckPlace place;
};

/// The deck's `sweep: refine:`, or nullopt without one. Throws DeckError naming the field for
/// an unknown analysis, a quantity it cannot give or a name it does not have, a tolerance
/// outside (0, 1), runs outside [the sweep's values, kMaxSweepValues], or values that do not
/// ascend.
std::optional<DeckSweepRefinement> readSweepRefinement(const DeckSource& source, const Deck& deck);

}  // namespace beamrotor

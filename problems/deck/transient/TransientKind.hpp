// The transient analysis' row in the table of analysis kinds (problems/deck/AnalysisKinds.hpp);
// a periodic steady state (`periodic: true`) is one of its settings, not a kind of its own.
#pragma once

#include "problems/deck/AnalysisRow.hpp"
#include "problems/deck/transient/DeckTransient.hpp"

namespace beamrotor {

struct TransientSpec {
  static constexpr std::string_view deckType = "transient";
  static constexpr std::array answers{Quantity::Kind::historyMax, Quantity::Kind::historyMin,
                                      Quantity::Kind::historyMaxAbs, Quantity::Kind::historyAt};
  static constexpr bool needsMass = true;
  void read(const reader::Context& c, const Field& f);
  DeckTransient run;  ///< the integration, its loads and what it records
};

}  // namespace beamrotor

// The transient analysis' row in the table of analysis kinds (problems/deck/AnalysisKinds.hpp);
// a periodic steady state (`periodic: true`) is one of its settings, not a kind of its own.
#pragma once

#include "problems/deck/AnalysisRow.hpp"

namespace beamrotor {

struct TransientSpec {
  static constexpr std::string_view deckType = "transient";
  static constexpr std::array answers{Quantity::Kind::historyMax, Quantity::Kind::historyMin,
                                      Quantity::Kind::historyMaxAbs, Quantity::Kind::historyAt};
  static constexpr bool needsMass = true;
  static void read(const reader::Context& c, const Field& f, DeckAnalysis& a);
};

}  // namespace beamrotor

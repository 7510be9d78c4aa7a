// The crank-slider drive's row in the table of analysis kinds
// (problems/deck/AnalysisKinds.hpp): a mechanism solved in closed form, with no model.
#pragma once

#include "problems/deck/AnalysisRow.hpp"
#include "problems/deck/crank/DeckCrank.hpp"

namespace beamrotor {

struct CrankSliderSpec {
  static constexpr std::string_view deckType = "crank-slider";
  static constexpr std::array answers{Quantity::Kind::crankSlider};
  static constexpr bool needsMass = false;
  void read(const reader::Context& c, const Field& f);
  static bool modelFree(const Field&) { return true; }
  DeckCrankSlider mechanism;
};

}  // namespace beamrotor

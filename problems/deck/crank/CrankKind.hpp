// The crank-slider drive's row in the table of analysis kinds
// (problems/deck/AnalysisKinds.hpp): a mechanism solved in closed form, with no model.
#pragma once

#include <array>
#include <string_view>

#include "problems/deck/Quantity.hpp"

namespace beamrotor {

class Field;
struct DeckAnalysis;
namespace reader {
struct Context;
}

struct CrankSliderSpec {
  static constexpr std::string_view deckType = "crank-slider";
  static constexpr std::array answers{Quantity::Kind::crankSlider};
  static void read(const reader::Context& c, const Field& f, DeckAnalysis& a);
  static bool modelFree(const Field&) { return true; }
};

}  // namespace beamrotor

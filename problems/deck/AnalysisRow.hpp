// What the rows of the table of analysis kinds (AnalysisKinds.hpp) are written with: each
// family's header declares its rows with these, without the reader's own types. A row is a
// struct with
//   static constexpr std::string_view deckType;   its `type:` in a deck
//   static constexpr std::array answers;          the check quantities it gives
//   static constexpr bool needsMass;              refused on a deck without inertia
//   static void read(const reader::Context&, const Field&, DeckAnalysis&);   its reader
// and optionally `static bool modelFree(const Field& entry)`: an entry that needs no model.
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

}  // namespace beamrotor

// What the rows of the table of analysis kinds (AnalysisKinds.hpp) are written with: each
// family's header declares its rows with these. A row is a struct holding the settings its
// deck entry gives, with
//   static constexpr std::string_view deckType;   its `type:` in a deck
//   static constexpr std::array answers;          the check quantities it gives
//   static constexpr bool needsMass;              refused on a deck without inertia
//   void read(const reader::Context&, const Field&);   its reader, filling the settings
// and optionally `static bool modelFree(const Field& entry)`: an entry that needs no model.
// Its runner (problems/run/DeckRunner.cpp) and writers (problems/output/) take the row by its
// type, so a row without them does not compile.
#pragma once

#include <array>
#include <string_view>

#include "problems/deck/Quantity.hpp"

namespace beamrotor {

class Field;
namespace reader {
struct Context;
}

}  // namespace beamrotor

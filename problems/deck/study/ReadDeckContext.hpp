// A reader's context over a deck already read: what fields read after the deck itself (a
// design study's, a sweep's refinement) need to evaluate expressions with the deck's
// parameters and to resolve quantities exactly as the deck's checks are resolved.
#pragma once

#include <string>

#include "problems/deck/Deck.hpp"
#include "problems/deck/ReaderContext.hpp"
#include "problems/deck/parse/DeckSource.hpp"

namespace beamrotor {

/// A copy of the deck read from `source` and a reader context on it, its parameters and
/// derived values defined with their units.
struct ReadDeckContext {
  Deck deck;
  reader::Context c;
  ReadDeckContext(const DeckSource& source, const Deck& base)
      : deck(base), c{Field::root(*source.tree), deck, {}, {}, {}, {}, {}, {}, {}, {}, {}} {
    auto define = [&](const std::string& name, double value) {
      Amount a{value, {}, false};
      for (const auto& [named, d] : deck.dimensions)
        if (named == name) a.dimension = d;
      c.evaluator.define(name, a);
    };
    for (const auto& [name, value] : deck.parameters) define(name, value);
    for (const auto& [name, value] : deck.derived) define(name, value);
  }
};

}  // namespace beamrotor

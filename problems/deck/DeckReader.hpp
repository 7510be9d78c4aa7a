// Reads a deck: YAML tree -> Deck, with every expression evaluated for one set of parameter
// values and every field validated. The format is described in problems/deck/FORMAT.md and
// by example in problems/*.yaml.
#pragma once

#include <vector>

#include "problems/deck/Deck.hpp"
#include "problems/deck/parse/DeckSource.hpp"
#include "problems/deck/parse/Expression.hpp"
#include "problems/deck/study/Overrides.hpp"

namespace beamrotor {

/// Most beam elements a deck may ask for (a line of 1e5 elements is already far finer than any
/// beam needs; the cap keeps a typo such as `size: 1e-9` from exhausting memory).
inline constexpr int kMaxElements = 100000;
/// Most values a sweep may take.
inline constexpr int kMaxSweepValues = 1000;
/// Most modes a modal analysis may ask for.
inline constexpr int kMaxModes = 100;
/// Most parameters and derived values together (every expression may use each of them).
inline constexpr int kMaxNamedValues = 10000;
/// Most analyses, and most checks, in one deck.
inline constexpr int kMaxAnalyses = 1000;

/// The deck with `overrides` replacing parameter values. Throws DeckError naming the file,
/// line, column and field of the first problem found.
Deck readDeck(const DeckSource& source, const std::vector<ParameterOverride>& overrides = {});

/// readDeck() for one of many readings of the same deck (a design study's points): what an
/// earlier reading sharing `memo` evaluated comes from its byte code (ExpressionMemo), the
/// rest is read as readDeck() reads it. The deck read is the same, bit for bit.
Deck readDeck(const DeckSource& source, const std::vector<ParameterOverride>& overrides,
              ExpressionMemo& memo);

}  // namespace beamrotor

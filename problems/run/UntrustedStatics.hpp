// A static solution whose measured round-off leaves no digit to trust fails its analysis
// (issue 44): a 1.2 m cantilever of 20,000 elements is 95 % off, of 50,000 elements 100 %,
// and warning about it (OverRefinementWarning.hpp) is not enough for a number a design rests
// on. The failure names the estimate and the remedy: the cheapest adequate mesh that the
// `accuracy:` search (AdequateModel.hpp) finds for the deck, where it applies. A static
// analysis with `accept_round_off: true` keeps such a solution (with the warning).
#pragma once

#include <string>

#include "fem/model/Model.hpp"
#include "fem/model/Results.hpp"
#include "problems/deck/Deck.hpp"

namespace beamrotor {

/// A measured round-off (relative, StaticResult::roundOff) at or above this leaves no digit
/// of the solution to trust: not even its sign.
inline constexpr double kNoTrustedDigit = 1;

/// The relative accuracy the remedy's `accuracy:` search aims at.
inline constexpr double kRemedyAccuracy = 1e-6;

/// Throws std::runtime_error (the analysis fails) when `r`, a static solution of `model` built
/// from `deck` (`what`: "" or "load case NAME"), leaves no digit to trust.
void refuseUntrustedStatics(const Deck& deck, const Model& model, const StaticResult& r,
                            const std::string& what = {});

/// `deck` with every static analysis keeping such solutions: for the `accuracy:` search,
/// which measures round-off itself, and its yardstick, the deck's own mesh.
Deck acceptingRoundOff(Deck deck);

}  // namespace beamrotor

// Solving a read deck: build its model, run its analyses in order, evaluate its checks.
#pragma once

#include <functional>
#include <vector>

#include "fem/solvers/SymbolicReuse.hpp"
#include "problems/deck/Deck.hpp"
#include "problems/deck/parse/DeckSource.hpp"
#include "problems/deck/study/Overrides.hpp"
#include "problems/run/RunResult.hpp"

namespace beamrotor {

/// What a run that ran out of memory says (std::bad_alloc is caught where it can be named).
inline constexpr const char* kOutOfMemory =
    "out of memory: the model, its factorisation or its results do not fit (use fewer "
    "elements, modes, frames or samples)";

/// What a caller that runs many decks of one structure one after another keeps between the
/// runs (the points of a design study): the symbolic analysis of the static systems.
struct RunCache {
  SymbolicReuse statics;
};

/// One run of a deck for its current parameter values. Throws DeckError for input the core
/// rejects while building, DeckSolveError (naming the analysis) when an analysis fails. With
/// `cache`, static systems of the pattern an earlier run left there skip their analysis.
RunResult runDeck(const Deck& deck, RunCache* cache = nullptr);

/// Called after each sweep value is solved: (values done, values in all).
using SweepProgress = std::function<void(int done, int total)>;

/// A change applied to the deck after each reading (e.g. a command-line formulation).
using DeckAdjustment = std::function<void(Deck&)>;

/// Runs deck.sweep: the source re-read and re-solved for each value of the swept parameter
/// (so a parameter may move points, supports and loads), `adjust` applied after each reading.
/// `base` is the deck read with `overrides` and must have a sweep. A DeckError or
/// DeckSolveError at one value names it.
SweepResult runSweep(const DeckSource& source, const std::vector<ParameterOverride>& overrides,
                     const Deck& base, const SweepProgress& progress = {},
                     const DeckAdjustment& adjust = {});

}  // namespace beamrotor

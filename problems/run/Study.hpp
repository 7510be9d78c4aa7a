// A deck read with its command-line overrides and solved: one run, or one run per value of
// its sweep. The entry point the command line and the tests share.
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "problems/deck/Deck.hpp"
#include "problems/deck/parse/DeckSource.hpp"
#include "problems/run/DeckRunner.hpp"
#include "problems/run/RunResult.hpp"

namespace beamrotor {

/// What to read and how.
struct StudyRequest {
  std::string deckPath;
  std::vector<std::string> sets;  ///< "NAME=VALUE" overrides, as typed
  bool noSweep = false;           ///< solve the parameters' own values even if the deck sweeps
  std::string sweep;              ///< "NAME=FROM:TO:STEPS" or "NAME=V1,V2": replaces the deck's
  std::string formulation;        ///< "timoshenko" or "euler-bernoulli" for every beam; "": deck's
};

/// The deck as read (base parameter values) and what solving it produced.
struct Study {
  Deck deck;
  std::optional<RunResult> run;      ///< when the deck has no sweep (or it was switched off)
  std::optional<SweepResult> sweep;  ///< otherwise
};

/// Reads the file, applies the overrides and solves. Throws DeckError (bad input) or
/// DeckSolveError (an analysis failed).
Study solveStudy(const StudyRequest& request, const SweepProgress& progress = {});

/// The same for deck text already in memory (tests); request.deckPath names it in messages.
Study solveStudyText(const std::string& text, const StudyRequest& request);

}  // namespace beamrotor

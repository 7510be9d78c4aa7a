// How every deck-reading command ends: the deck's diagnostics become one line on `err` and an
// exit code (ExitCodes.hpp), whatever the command was doing.
#pragma once

#include <ostream>

#include "problems/cli/ExitCodes.hpp"
#include "problems/deck/parse/DeckError.hpp"

namespace beamrotor::cli {

/// Runs `body` (returning an exit code); a DeckError exits kInputError, a DeckSolveError
/// kSolveFailure, each after printing its message.
template <class Body>
int guarded(std::ostream& err, Body&& body) {
  try {
    return body();
  } catch (const DeckError& e) {
    err << e.what() << "\n";
    return kInputError;
  } catch (const DeckSolveError& e) {
    err << e.what() << "\n";
    return kSolveFailure;
  }
}

}  // namespace beamrotor::cli

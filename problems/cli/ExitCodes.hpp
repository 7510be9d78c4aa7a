// Exit codes of the beamrotor command line, for scripts and CI.
#pragma once

namespace beamrotor::cli {

enum ExitCode : int {
  kOk = 0,            ///< solved (and, for `check`, every applicable check passed)
  kSolveFailure = 1,  ///< the deck is valid but an analysis failed, or outputs could not be written
  kInputError = 2,    ///< malformed deck, bad override or bad command line
  kChecksFailed = 3,  ///< `check`: at least one check failed
};

}  // namespace beamrotor::cli

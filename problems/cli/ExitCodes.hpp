// Exit codes of the beamrotor command line, for scripts and CI. A run stopped by SIGINT or
// SIGTERM ends by that signal instead (the shell shows 130 or 143), after a study has written
// the rows it had (problems/output/files/Interruption.hpp).
#pragma once

namespace beamrotor::cli {

enum ExitCode : int {
  kOk = 0,            ///< solved (and, for `check`, every applicable check passed)
  kSolveFailure = 1,  ///< the deck is valid but an analysis failed (for a study: no point
                      ///< succeeded), or outputs could not be written
  kInputError = 2,    ///< malformed deck, bad override or bad command line
  kChecksFailed = 3,  ///< `check`: at least one check failed
};

}  // namespace beamrotor::cli

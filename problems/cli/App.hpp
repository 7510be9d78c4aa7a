// The beamrotor command line: parses arguments with CLI11 and dispatches to the subcommands.
#pragma once

#include <ostream>

namespace beamrotor::cli {

/// Runs the command line; returns the process exit code (see ExitCodes.hpp). Never throws.
int runCommandLine(int argc, const char* const* argv, std::ostream& out, std::ostream& err);

}  // namespace beamrotor::cli

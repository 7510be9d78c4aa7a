// The beamrotor executable: `beamrotor solve DECK`, `beamrotor check DECK`, `--help`,
// `--version`. Everything lives in problems/cli; this only connects it to the process.
#include <iostream>

#include "problems/cli/App.hpp"

int main(int argc, char** argv) {
  return beamrotor::cli::runCommandLine(argc, argv, std::cout, std::cerr);
}

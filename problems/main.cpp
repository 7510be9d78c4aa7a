// The beamrotor executable: `beamrotor solve DECK`, `beamrotor check DECK`, `--help`,
// `--version`. Everything lives in problems/cli; this only connects it to the process.
#include <iostream>

#include "fem/solvers/HeapReserve.hpp"
#include "problems/cli/App.hpp"

int main(int argc, char** argv) {
  beamrotor::keepFreedMemory();
  return beamrotor::cli::runCommandLine(argc, argv, std::cout, std::cerr);
}

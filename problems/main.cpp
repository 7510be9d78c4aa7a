// The beamrotor executable: `beamrotor solve DECK`, `beamrotor check DECK`, `--help`,
// `--version`. Everything lives in problems/cli; this only connects it to the process.
#include <iostream>

#include "fem/solvers/BlasThreads.hpp"
#include "fem/solvers/HeapReserve.hpp"
#include "problems/cli/App.hpp"
#include "problems/cli/HugePages.hpp"
#include "problems/output/files/Interruption.hpp"

int main(int argc, char** argv) {
  beamrotor::cli::restartWithHugePages(argv);
  beamrotor::keepFreedMemory();
  beamrotor::useOneBlasThreadPerCall();
  const int code = beamrotor::cli::runCommandLine(argc, argv, std::cout, std::cerr);
  // Interrupted while writing: the temporary directory is gone; now end as the signal asked.
  std::cout.flush();
  beamrotor::endIfInterrupted();
  // The summary is output like any file: a failed write (a full device) is not success.
  if (!std::cout) {
    std::cerr << "beamrotor: cannot write the summary to standard output\n";
    return code == 0 ? 1 : code;
  }
  return code;
}

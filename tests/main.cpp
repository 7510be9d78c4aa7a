// The one doctest main for the whole tests/ tree.
#define DOCTEST_CONFIG_IMPLEMENT
#include <doctest/doctest.h>

#include "fem/solvers/BlasThreads.hpp"

int main(int argc, char** argv) {
  beamrotor::useOneBlasThreadPerCall();  // as the command line runs
  return doctest::Context(argc, argv).run();
}

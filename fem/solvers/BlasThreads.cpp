#include "fem/solvers/BlasThreads.hpp"

// OpenBLAS's own entry point, declared weak: absent (null) when another BLAS is linked.
extern "C" void openblas_set_num_threads(int threads) __attribute__((weak));

namespace beamrotor {

void useOneBlasThreadPerCall() {
  if (openblas_set_num_threads) openblas_set_num_threads(1);
}

}  // namespace beamrotor

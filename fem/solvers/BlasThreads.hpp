// The BLAS under ARPACK, CHOLMOD and UMFPACK is the threaded build of Debian's OpenBLAS
// (libopenblas0-pthread, pinned in CMakeLists.txt), run with one thread per call.
// Threaded, because that build may be called from several threads at once: the serial build
// (libopenblas0-serial) shares its work buffers between calls without a lock, and on Debian
// 12's 0.3.21 two threads calling it at once got wrong results (dgemv 862 of 120000, dgemm
// 214 of 40000 products differing from the same product alone); beamrotor calls BLAS from
// several threads when a study solves points side by side or Python threads solve decks.
// One thread per call, because OpenBLAS would otherwise split large products over every core,
// so the last bits of a result would depend on the machine, and its threads would compete
// with the passes over elements and the study's points for the same cores.
#pragma once

namespace beamrotor {

/// Sets OpenBLAS's threads per call to one; a no-op with another BLAS. Call once at start-up
/// (the command line, the tests and the Python module do), before any solve.
void useOneBlasThreadPerCall();

}  // namespace beamrotor

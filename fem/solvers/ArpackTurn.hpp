// ARPACK keeps the state of a reverse-communication run (the *aupd calls up to the *eupd that
// ends it) in Fortran SAVE variables: one copy per process, not per run. Two runs on two
// threads at once overwrite each other's state, which ends in wrong eigenvalues, ARPACK
// errors or a corrupted heap (two Python threads calling beamrotor.solve on modal decks
// crashed the interpreter). Every ARPACK run in this program therefore holds the one turn
// below from its first *aupd call to its *eupd: runs on other threads wait, everything else
// (assembly, factorisations) still runs side by side.
#pragma once

#include <mutex>

namespace beamrotor {

/// Held by one ARPACK run at a time, process-wide, while it lives.
class ArpackTurn {
 public:
  ArpackTurn();

 private:
  std::unique_lock<std::mutex> held_;
};

}  // namespace beamrotor

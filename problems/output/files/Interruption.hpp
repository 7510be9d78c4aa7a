// Ctrl-C, `kill` or a closed terminal while results are being written: the signal is recorded
// (not acted on at once), the writers stop at their next file and unwind, which removes the
// half-written temporary directory, and the process then ends by the same signal. A writer
// that can keep what it has (a design study's rows) acknowledges the signal instead, writes
// its partial results, and the process ends by the signal after that. Outside a
// write the signals keep their usual effect (nothing is on disk to clean up while solving).
#pragma once

#include <stdexcept>

namespace beamrotor {

/// What a writer throws when a deferred signal arrived.
class Interrupted : public std::runtime_error {
 public:
  explicit Interrupted(int signal);
  int signal() const { return signal_; }

 private:
  int signal_;
};

/// While one exists, SIGINT, SIGTERM and SIGHUP are recorded instead of ending the process; a
/// second such signal ends it at once (the next run sweeps what is left, see
/// AtomicDirectory.hpp). The previous handlers come back when the last one is destroyed.
class DeferredSignals {
 public:
  DeferredSignals();
  ~DeferredSignals();
  DeferredSignals(const DeferredSignals&) = delete;
  DeferredSignals& operator=(const DeferredSignals&) = delete;
};

/// Throws Interrupted when a signal was recorded and not acknowledged. Writers call it before
/// each file.
void throwIfInterrupted();

/// A writer that stops on the recorded signal but keeps what it computed (a design study
/// writing the rows it has) takes the signal on: throwIfInterrupted no longer throws for it,
/// so the partial results can be written. A second signal still ends the process at once, and
/// endIfInterrupted still ends it by the first.
void acknowledgeInterruption();

/// The recorded signal, 0 when none.
int pendingInterruption();

/// Forgets a recorded (or acknowledged) signal (for tests that raise one on purpose).
void clearInterruption();

/// Ends the process by the recorded signal, with its default action, when there is one (so
/// that a shell sees the process as killed by it). Called last in main.
void endIfInterrupted();

}  // namespace beamrotor

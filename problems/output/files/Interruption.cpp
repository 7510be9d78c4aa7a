// Deferred signals while writing (see Interruption.hpp).
#include "problems/output/files/Interruption.hpp"

#include <signal.h>

#include <cstring>
#include <string>

namespace beamrotor {

namespace {

constexpr int kDeferred[] = {SIGINT, SIGTERM, SIGHUP};
constexpr int kCount = int(sizeof kDeferred / sizeof kDeferred[0]);

volatile sig_atomic_t pending = 0;
volatile sig_atomic_t acknowledged = 0;  // the pending signal is being handled by its writer
int depth = 0;  // nested DeferredSignals (main thread only)
struct sigaction previous[kCount];

extern "C" void recordSignal(int signal) {
  if (pending == 0) {
    pending = signal;
    return;
  }
  // Asked twice: stop now, leaving the temporary directory to the next run's sweep.
  ::signal(signal, SIG_DFL);
  ::raise(signal);
}

}  // namespace

Interrupted::Interrupted(int signal)
    : std::runtime_error(std::string("interrupted by ") +
                         (signal == SIGINT    ? "SIGINT"
                          : signal == SIGTERM ? "SIGTERM"
                          : signal == SIGHUP  ? "SIGHUP"
                                              : "signal " + std::to_string(signal))),
      signal_(signal) {}

DeferredSignals::DeferredSignals() {
  if (depth++ > 0) return;
  struct sigaction action;
  std::memset(&action, 0, sizeof action);
  action.sa_handler = recordSignal;
  sigemptyset(&action.sa_mask);
  action.sa_flags = SA_RESTART;
  for (int i = 0; i < kCount; ++i) {
    sigaction(kDeferred[i], nullptr, &previous[i]);
    // A signal the caller ignores (nohup) stays ignored.
    if (previous[i].sa_handler != SIG_IGN) sigaction(kDeferred[i], &action, nullptr);
  }
}

DeferredSignals::~DeferredSignals() {
  if (--depth > 0) return;
  for (int i = 0; i < kCount; ++i) sigaction(kDeferred[i], &previous[i], nullptr);
}

void throwIfInterrupted() {
  if (const int signal = pending; signal != 0 && !acknowledged) throw Interrupted(signal);
}

void acknowledgeInterruption() {
  if (pending != 0) acknowledged = 1;
}

int pendingInterruption() {
  return pending;
}

void clearInterruption() {
  pending = 0;
  acknowledged = 0;
}

void endIfInterrupted() {
  const int signal = pending;
  if (signal == 0) return;
  ::signal(signal, SIG_DFL);
  ::raise(signal);
}

}  // namespace beamrotor

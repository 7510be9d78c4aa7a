// A one-line progress bar on stderr for long sweeps, shown only when stderr is a terminal.
#pragma once

#include <ostream>

namespace beamrotor::cli {

class ProgressBar {
 public:
  /// Draws on `out` when `enabled`; otherwise every call does nothing.
  ProgressBar(std::ostream& out, bool enabled) : out_(out), enabled_(enabled) {}
  /// Clears the bar's line.
  ~ProgressBar();
  ProgressBar(const ProgressBar&) = delete;
  ProgressBar& operator=(const ProgressBar&) = delete;

  /// Redraws the bar: `done` of `total` items finished.
  void update(int done, int total);

  /// Whether a sweep of `total` values deserves a bar: stderr is a terminal and the sweep
  /// has enough values to take a noticeable time.
  static bool wanted(int total);

 private:
  std::ostream& out_;
  bool enabled_;
  bool drawn_ = false;
};

}  // namespace beamrotor::cli

#include "problems/cli/Progress.hpp"

#include <unistd.h>

#include <string>

namespace beamrotor::cli {

namespace {
constexpr int kWidth = 40;           // characters of bar
constexpr int kShortestSweep = 10;   // fewer values finish before a bar is worth drawing
}  // namespace

bool ProgressBar::wanted(int total) { return total >= kShortestSweep && isatty(STDERR_FILENO); }

void ProgressBar::update(int done, int total) {
  if (!enabled_ || total <= 0) return;
  const int filled = kWidth * done / total;
  out_ << "\r[" << std::string(filled, '#') << std::string(kWidth - filled, '.') << "] " << done
       << "/" << total << std::flush;
  drawn_ = true;
}

ProgressBar::~ProgressBar() {
  if (drawn_) out_ << "\r" << std::string(kWidth + 20, ' ') << "\r" << std::flush;
}

}  // namespace beamrotor::cli

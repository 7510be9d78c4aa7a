// Every shipped deck's closed-form checks, run through the library (as `beamrotor check`
// does), collected as rows for the verification report.
#pragma once

#include <filesystem>
#include <string>
#include <vector>

#include "problems/run/RunResult.hpp"

namespace beamrotor::verify {

/// A check that did not apply to a run, and why (its `when:` condition was false there).
struct NotApplied {
  std::string label;  ///< the run, as in DeckChecks::checks
  std::string name;
  std::string why;  ///< e.g. "when: speed_rpm == 3000 is false here"
};

/// The checks of one deck, or why it could not be solved.
struct DeckChecks {
  std::string deck;                                   ///< file name, e.g. "cantilever.yaml"
  std::string title;                                  ///< the deck's title
  std::vector<std::pair<std::string, Check>> checks;  ///< (run label, check); label empty
                                                      ///< unless the deck sweeps
  std::vector<NotApplied> notApplied;  ///< checks left out at these parameter values
  std::string error;   ///< the one-line diagnostic when reading or solving failed
  double seconds = 0;  ///< wall time of the solve
};

/// Solves each deck (its own sweep included) and collects its checks; never throws for a
/// deck that fails, recording the failure instead.
std::vector<DeckChecks> runDeckChecks(const std::vector<std::filesystem::path>& decks);

/// The *.yaml files directly in dir, sorted.
std::vector<std::filesystem::path> decksIn(const std::filesystem::path& dir);

}  // namespace beamrotor::verify

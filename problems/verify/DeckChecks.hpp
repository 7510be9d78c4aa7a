// Every shipped deck's closed-form checks, run through the library (as `beamrotor check`
// does), collected as rows for the verification report.
#pragma once

#include <filesystem>
#include <string>
#include <vector>

#include "problems/run/RunResult.hpp"

namespace beamrotor::verify {

/// The checks of one deck, or why it could not be solved.
struct DeckChecks {
  std::string deck;                                   ///< file name, e.g. "cantilever.yaml"
  std::string title;                                  ///< the deck's title
  std::vector<std::pair<std::string, Check>> checks;  ///< (run label, check); label empty
                                                      ///< unless the deck sweeps
  std::string error;   ///< the one-line diagnostic when reading or solving failed
  double seconds = 0;  ///< wall time of the solve
};

/// Solves each deck (its own sweep included) and collects its checks; never throws for a
/// deck that fails, recording the failure instead.
std::vector<DeckChecks> runDeckChecks(const std::vector<std::filesystem::path>& decks);

/// The *.yaml files directly in dir, sorted.
std::vector<std::filesystem::path> decksIn(const std::filesystem::path& dir);

}  // namespace beamrotor::verify

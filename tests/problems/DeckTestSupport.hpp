// Shared helpers for the deck tests: where the decks and fixtures live, and running the
// beamrotor executable.
#pragma once

#include <filesystem>
#include <string>
#include <vector>

namespace beamrotor::test {

/// problems/ in the source tree.
inline std::filesystem::path problemsDir() {
  return std::filesystem::path(BEAMROTOR_SOURCE_DIR) / "problems";
}

/// The decks shipped in problems/, sorted.
std::vector<std::filesystem::path> shippedDecks();

/// What running the executable produced.
struct ProcessResult {
  int exitCode = -1;
  std::string out;
  std::string err;
};

/// Runs BEAMROTOR_EXE with `arguments` (each shell-quoted) from the source directory.
ProcessResult runBeamrotor(const std::vector<std::string>& arguments);

/// A fresh empty directory under the system temp directory, unique to this process.
std::filesystem::path scratchDir(const std::string& name);

}  // namespace beamrotor::test

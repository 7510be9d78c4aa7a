// Shared helpers for the deck tests: where the decks and fixtures live, and running the
// beamrotor executable.
#pragma once

#include <cstdio>
#include <filesystem>
#include <nlohmann/json.hpp>
#include <string>
#include <utility>
#include <vector>

#include "problems/deck/parse/DeckError.hpp"
#include "problems/run/Study.hpp"

namespace beamrotor::test {

/// A `--set` override NAME=VALUE with the value at full precision.
inline std::string setting(const std::string& name, double value) {
  char buffer[64];
  std::snprintf(buffer, sizeof buffer, "%s=%.17g", name.c_str(), value);
  return buffer;
}

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

/// Runs BEAMROTOR_EXE with `arguments` (each shell-quoted) in `workingDir` (default: the
/// source directory) with `environment` (NAME=VALUE) added, stopped after 120 s (exit code
/// 124) so that a hang fails a test instead of stalling it.
ProcessResult runBeamrotor(const std::vector<std::string>& arguments,
                           const std::filesystem::path& workingDir = BEAMROTOR_SOURCE_DIR,
                           const std::vector<std::string>& environment = {});

/// Starts BEAMROTOR_EXE with `arguments` in `dir` without waiting for it (stdout and stderr
/// into dir/log, the default actions of SIGINT and SIGTERM restored); returns its pid.
int startBeamrotor(const std::filesystem::path& dir, const std::vector<std::string>& arguments);

/// Waits for process `pid` at most `seconds` (then kills it, and the test fails); returns its
/// wait status.
int waitForProcess(int pid, double seconds = 120);

/// A file's bytes as a string ("" when it cannot be read).
std::string fileContents(const std::filesystem::path& file);

/// A CSV file as rows of cells, header first, an empty cell kept as "" (for tables whose
/// cells hold no quoted commas).
std::vector<std::vector<std::string>> csvCells(const std::filesystem::path& file);

/// The position of the header cell `name`, bare or quoted; FAILs the test when there is none.
std::size_t csvColumn(const std::vector<std::string>& header, const std::string& name);

/// text inside single quotes for /bin/sh.
std::string shellQuoted(const std::string& text);

/// A fresh empty directory under the system temp directory, unique to this process.
std::filesystem::path scratchDir(const std::string& name);

/// A shipped deck solved by the executable into a scratch directory.
struct SolvedDeck {
  ProcessResult process;
  std::filesystem::path dir;  ///< the results; remove dir.parent_path() when done
  /// A JSON file of the results, parsed.
  nlohmann::json json(const std::string& file) const;
  /// A file of the results as text.
  std::string text(const std::string& file) const;
};

/// The last analysis of type `type` in a results.json document (null when it has none).
nlohmann::json analysisOfType(const nlohmann::json& results, const std::string& type);

/// `beamrotor solve problems/<deck> --out DIR` into a fresh scratch directory `scratch`;
/// REQUIREs that it succeeds (showing its stderr otherwise).
SolvedDeck solveShippedDeckToScratch(const std::string& deck, const std::string& scratch);

/// A request to solve the shipped deck problems/<name> with `--set` overrides, its own sweep
/// switched off.
StudyRequest shippedDeckRequest(const std::string& name, std::vector<std::string> sets = {});

/// The shipped deck problems/<name> solved as shippedDeckRequest(name) asks.
Study solveShippedDeck(const std::string& name);

/// The rotor mass of the shipped compressor decks (compressor_rotor*.yaml): a 90 mm steel shaft
/// 1.3 m long and two impellers 380 mm by 70 mm on it, a closed form of their geometry (kg).
double compressorRotorMass();

/// Deck text written in a test, read and solved as if it were the file `path` (which names
/// it in messages).
Study solveDeckText(const std::string& text, const std::string& path);

/// The DeckError that reading `text` as the file `path` raises (REQUIREs one).
DeckError readingError(const std::string& text, const std::string& path);

/// The runs of a solved study: its one run, or one per sweep value.
std::vector<const RunResult*> runsOf(const Study& study);

/// CHECKs that every check of every run passes (naming the failing ones); returns how many
/// ran.
int checkAllPass(const Study& study);

/// Reaction (N, N m) at `support` in the first static analysis of run.
double staticReaction(const RunResult& run, const std::string& support, Dof dof);

/// The value of a parameter or derived value of a read deck; throws when it has none.
double deckValue(const Deck& deck, const std::string& name);

}  // namespace beamrotor::test

// The hostile suite's harness: a case is a deck text and a command line run in a fresh sandbox
// directory, with what must come out of it (exit code, message shape). Every run is also held
// to the rules that hold for any input: nothing outside the paths the case may change is
// created, changed or removed (a payload's canary file included), and no file written holds a
// NaN or an infinity.
#pragma once

#include <filesystem>
#include <functional>
#include <string>
#include <vector>

#include "tests/problems/DeckTestSupport.hpp"

namespace beamrotor::test {

/// A steel rod of 1 m in 4 elements: materials, sections and segments of the decks below.
inline constexpr const char* kHostileBeam = R"(materials:
  - {name: steel, E: 200e9, nu: 0.3, rho: 7850}
sections:
  - {name: bar, shape: circle, D: 0.05}
segments:
  - {name: a, length: 1, section: bar, elements: 4}
)";

/// A cantilever with a static and a short transient analysis (one history with a unit) and a
/// check, with placeholders {title}, {unit} and {check} (YAML scalars, quotes included).
std::string hostileBaseDeck(const std::string& title = "Cantilever", const std::string& unit = "N",
                            const std::string& check = "tip deflection");

struct HostileCase {
  std::string name;
  std::string deck;  ///< written to deck.yaml in the sandbox unless empty
  /// Arguments; "{sandbox}" is replaced by the sandbox's absolute path.
  std::vector<std::string> arguments;
  int exitCode = 0;
  /// ECMAScript regex that stderr must contain (searched); empty: no requirement.
  std::string message;
  /// Relative paths the run may create or change (a directory: all inside it).
  std::vector<std::string> mayChange{"out"};
  /// Prepares the sandbox before the run (files in the way, fifos, ...).
  std::function<void(const std::filesystem::path&)> setup{};  // a table row may stop before it
  /// gnuplot runs (real charts) only when asked: charts cost most of a run's time.
  bool charts = false;
  /// Run as its own process (stopped after 120 s) rather than by calling the command line in
  /// this one (the default: about 100 times faster, the process start loading VTK being most
  /// of a short run): needed where a hang must end the run, or the process' end matters.
  bool process = false;
};

/// Runs the case and CHECKs everything (see the file comment); returns what the run did.
ProcessResult runHostileCase(const HostileCase& c);

/// The rows of a table, each run and checked (with its name CAPTUREd); returns how many ran.
int runHostileCases(const std::vector<HostileCase>& cases);

/// Where a deck error about `field` points: "deck.yaml:LINE:COL: FIELD: " as a regex.
std::string atField(const std::string& field);

}  // namespace beamrotor::test

// The errors a deck run reports to the user: DeckError for input the reader rejects (exit code
// 2) and DeckSolveError for a well-formed deck whose analysis fails (exit code 1). Both carry
// where in the deck the problem lies and format themselves as one line:
//   problems/x.yaml:12:7: segments[1].length: must be positive, got -0.5
#pragma once

#include <stdexcept>
#include <string>

namespace YAML {
struct Mark;
}

namespace beamrotor {

/// A position in a deck: 1-based line and column (0 when unknown) and the dotted path of the
/// field there, e.g. "segments[1].length" (empty for the file as a whole).
struct DeckPlace {
  int line = 0;
  int column = 0;
  std::string field;
};

/// The place of a yaml-cpp mark (1-based); unknown (all 0) for a null or negative mark.
DeckPlace placeOf(const YAML::Mark& mark);

/// "file:line:column: field: message" with the unknown parts left out, on one line (newlines
/// inside the message become spaces).
std::string formatDeckMessage(const std::string& file, const DeckPlace& place,
                              const std::string& message);

/// Base of both deck diagnostics: remembers its parts so tests and tools can inspect them.
class DeckDiagnostic : public std::runtime_error {
 public:
  DeckDiagnostic(std::string file, DeckPlace place, std::string message);
  /// The deck's path as the user gave it.
  const std::string& file() const { return file_; }
  /// Where in the deck; line and column 1-based, 0 when unknown.
  const DeckPlace& place() const { return place_; }
  /// The message without file and place.
  const std::string& message() const { return message_; }

 private:
  std::string file_;
  DeckPlace place_;
  std::string message_;
};

/// The deck (or a command-line override of it) is malformed: syntax, types, ranges, names.
class DeckError : public DeckDiagnostic {
 public:
  using DeckDiagnostic::DeckDiagnostic;
};

/// The deck is well formed but an analysis failed (mechanism, singular system); place names
/// the analysis.
class DeckSolveError : public DeckDiagnostic {
 public:
  using DeckDiagnostic::DeckDiagnostic;
};

}  // namespace beamrotor

#include "problems/deck/parse/DeckError.hpp"

#include <yaml-cpp/mark.h>

namespace beamrotor {

namespace {

/// Newlines and tabs become single spaces so every diagnostic stays on one line.
std::string oneLine(const std::string& text) {
  std::string out;
  out.reserve(text.size());
  for (char c : text) {
    const bool space = c == '\n' || c == '\r' || c == '\t';
    if (space && (out.empty() || out.back() == ' ')) continue;
    out.push_back(space ? ' ' : c);
  }
  while (!out.empty() && out.back() == ' ') out.pop_back();
  return out;
}

}  // namespace

DeckPlace placeOf(const YAML::Mark& mark) {
  if (mark.is_null() || mark.line < 0) return {};
  return {mark.line + 1, mark.column + 1, ""};
}

std::string formatDeckMessage(const std::string& file, const DeckPlace& place,
                              const std::string& message) {
  std::string out = file.empty() ? std::string("<deck>") : file;
  if (place.line > 0) {
    out.append(":").append(std::to_string(place.line));
    if (place.column > 0) out.append(":").append(std::to_string(place.column));
  }
  out.append(": ");
  if (!place.field.empty()) out.append(place.field).append(": ");
  out.append(message);
  return oneLine(out);
}

DeckDiagnostic::DeckDiagnostic(std::string file, DeckPlace place, std::string message)
    : std::runtime_error(formatDeckMessage(file, place, message)),
      file_(std::move(file)),
      place_(std::move(place)),
      message_(std::move(message)) {}

}  // namespace beamrotor

// Turning a deck file (or text) into its tree (DeckTree.hpp), rejecting what is not a deck at
// all: a missing or unreadable file, an empty, oversized or binary one, YAML syntax errors, and
// aliases that expand without end.
#pragma once

#include <filesystem>
#include <memory>
#include <string>

#include "problems/deck/parse/DeckTree.hpp"

namespace beamrotor {

/// A deck's tree and the name it goes by in messages.
struct DeckSource {
  std::string path;  ///< as the user gave it, e.g. "problems/pump_rod.yaml"
  std::string stem;  ///< file name without directory and extension, e.g. "pump_rod"
  std::shared_ptr<const DeckTree> tree;  ///< its root is the top-level map
};

/// Largest deck accepted (bytes). Hand-written decks are a few kilobytes; a generated frame of
/// 10^5 members, each a line of about 90 characters, is about 9 MB.
inline constexpr std::size_t kLargestDeck = 16 * 1024 * 1024;

/// Reads and parses a deck file. Throws DeckError naming the file (and the line for syntax
/// errors).
DeckSource loadDeckFile(const std::filesystem::path& path);

/// Parses deck text already in memory; `path` names it in messages. Throws DeckError.
DeckSource parseDeckText(const std::string& text, const std::string& path);

}  // namespace beamrotor

// A deck's YAML tree copied once into plain nodes that Field (Field.hpp) walks. A design study
// reads its deck again at every point; walking yaml-cpp's own nodes costs a reference count
// and an allocation at every step, these cost a pointer. Kinds and scalar texts are yaml-cpp's
// (a plain `~`, `null` or nothing is null), places are the nodes' marks.
#pragma once

#include <cstdint>
#include <deque>
#include <memory>
#include <string>
#include <utility>
#include <vector>

#include <yaml-cpp/yaml.h>

#include "problems/deck/parse/DeckError.hpp"

namespace beamrotor {

struct DeckNode {
  enum class Kind : std::uint8_t { null, scalar, list, map };
  Kind kind = Kind::null;
  int line = 0, column = 0;  ///< 1-based; 0 where yaml-cpp gives no mark
  std::string text;   ///< a scalar's text
  std::vector<const DeckNode*> items;                              ///< a list's items
  std::vector<std::pair<const DeckNode*, const DeckNode*>> entries;  ///< a map's keys, values
  /// A map whose keys are all scalars, none twice (what a deck's maps must be).
  bool plainUniqueKeys = false;
};

class DeckTree {
 public:
  /// Most nodes a deck may hold once its aliases are expanded (each alias is a copy of what it
  /// names): a deck of kLargestDeck bytes written out holds at most about half as many.
  static constexpr std::size_t kMostNodes = 4000000;
  /// Deepest nesting of maps and lists (a deck needs a handful; an alias inside the list or
  /// map it names would otherwise nest without end).
  static constexpr int kDeepest = 200;

  /// The copy of `root`, read from `file`. Throws DeckError (naming `file` and the alias's
  /// place) when the copy exceeds kMostNodes or kDeepest.
  static std::shared_ptr<const DeckTree> fromYaml(const YAML::Node& root, std::string file);
  /// A tree of one scalar without a place (a quantity typed on the command line).
  static std::shared_ptr<const DeckTree> ofScalar(std::string text, std::string file);

  const DeckNode& root() const { return nodes_.front(); }
  const std::string& file() const { return file_; }

 private:
  explicit DeckTree(std::string file) : file_(std::move(file)) {}
  const DeckNode* copy(const YAML::Node& node, int depth);

  std::deque<DeckNode> nodes_;  ///< stable addresses; the root first
  std::string file_;
};

}  // namespace beamrotor

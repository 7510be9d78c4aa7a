#include "problems/deck/parse/DeckTree.hpp"

#include <algorithm>
#include <string_view>

namespace beamrotor {

namespace {

bool plainUniqueKeys(const std::vector<std::pair<const DeckNode*, const DeckNode*>>& entries) {
  std::vector<std::string_view> keys;
  keys.reserve(entries.size());
  for (const auto& [key, value] : entries) {
    if (key->kind != DeckNode::Kind::scalar) return false;
    keys.emplace_back(key->text);
  }
  std::sort(keys.begin(), keys.end());
  return std::adjacent_find(keys.begin(), keys.end()) == keys.end();
}

}  // namespace

const DeckNode* DeckTree::copy(const YAML::Node& node, int depth) {
  if (nodes_.size() >= kMostNodes)
    throw DeckError(file_, placeOf(node.Mark()),
                    "the deck holds more than " + std::to_string(kMostNodes) +
                        " values once its aliases (*name) are expanded");
  if (depth > kDeepest)
    throw DeckError(file_, placeOf(node.Mark()),
                    "maps and lists nested deeper than " + std::to_string(kDeepest) +
                        " levels (an alias inside the map or list it names?)");
  DeckNode& out = nodes_.emplace_back();
  const DeckPlace place = placeOf(node.Mark());
  out.line = place.line;
  out.column = place.column;
  switch (node.Type()) {
    case YAML::NodeType::Scalar:
      out.kind = DeckNode::Kind::scalar;
      out.text = node.Scalar();
      break;
    case YAML::NodeType::Sequence:
      out.kind = DeckNode::Kind::list;
      out.items.reserve(node.size());
      for (const YAML::Node& item : node) out.items.push_back(copy(item, depth + 1));
      break;
    case YAML::NodeType::Map:
      out.kind = DeckNode::Kind::map;
      out.entries.reserve(node.size());
      for (const auto& entry : node) {
        const DeckNode* key = copy(entry.first, depth + 1);
        out.entries.emplace_back(key, copy(entry.second, depth + 1));
      }
      out.plainUniqueKeys = plainUniqueKeys(out.entries);
      break;
    default:  // Null, Undefined
      out.kind = DeckNode::Kind::null;
  }
  return &out;
}

std::shared_ptr<const DeckTree> DeckTree::fromYaml(const YAML::Node& root, std::string file) {
  std::shared_ptr<DeckTree> tree(new DeckTree(std::move(file)));
  tree->copy(root, 0);
  return tree;
}

std::shared_ptr<const DeckTree> DeckTree::ofScalar(std::string text, std::string file) {
  std::shared_ptr<DeckTree> tree(new DeckTree(std::move(file)));
  DeckNode& node = tree->nodes_.emplace_back();
  node.kind = DeckNode::Kind::scalar;
  node.text = std::move(text);
  return tree;
}

}  // namespace beamrotor

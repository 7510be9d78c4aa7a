// Finding a deck's records by name in constant time while the reader is still appending them.
#pragma once

#include <cstddef>
#include <initializer_list>
#include <optional>
#include <string>
#include <unordered_map>
#include <unordered_set>
#include <vector>

namespace beamrotor::reader {

/// Positions of the records of a vector that only grows, by name: each record is indexed once,
/// when a lookup first finds it unindexed, and the first record of a name wins, as a search from
/// the front would. An empty name is never indexed.
class NameIndex {
 public:
  /// The position of the first record whose nameOf is `name` in `records`.
  template <class Records, class NameOf>
  std::optional<int> find(const Records& records, const std::string& name, NameOf nameOf) const {
    if (records.size() < indexed_) {  // the vector was replaced: index it afresh
      positions_.clear();
      indexed_ = 0;
    }
    for (; indexed_ < records.size(); ++indexed_) {
      const std::string& key = nameOf(records[indexed_]);
      if (!key.empty()) positions_.emplace(key, int(indexed_));
    }
    const auto it = positions_.find(name);
    if (it == positions_.end()) return std::nullopt;
    return it->second;
  }

 private:
  mutable std::unordered_map<std::string, int> positions_;
  mutable std::size_t indexed_ = 0;
};

/// The names a block has given out, in order, for refusing a second use of one.
class TakenNames {
 public:
  TakenNames() = default;
  TakenNames(std::initializer_list<std::string> reserved) {
    for (const std::string& name : reserved) claim(name);
  }
  /// False when `name` was taken before; otherwise takes it.
  bool claim(const std::string& name) {
    if (!set_.insert(name).second) return false;
    inOrder_.push_back(name);
    return true;
  }
  const std::vector<std::string>& inOrder() const { return inOrder_; }

 private:
  std::unordered_set<std::string> set_;
  std::vector<std::string> inOrder_;
};

}  // namespace beamrotor::reader

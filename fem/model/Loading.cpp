// A load case on the one model (see Loading.hpp).
#include "fem/model/Loading.hpp"

#include <algorithm>
#include <iterator>

namespace beamrotor {

Loading::Loading(std::vector<NodalLoad> nodal, std::vector<std::pair<int, ElementSpanLoad>> span)
    : nodal_(std::move(nodal)) {
  std::stable_sort(span.begin(), span.end(),
                   [](const auto& a, const auto& b) { return a.first < b.first; });
  for (const auto& [element, q] : span) {
    if (!span_.empty() && span_.back().first == element)
      span_.back().second += q;
    else
      span_.emplace_back(element, q);
  }
}

Loading Loading::combination(
    const std::vector<std::pair<std::shared_ptr<const Loading>, double>>& parts) {
  Loading out;
  out.parts_ = parts;
  for (const auto& [part, factor] : parts)
    for (NodalLoad l : part->nodal()) {
      l.value *= factor;
      out.nodal_.push_back(l);
    }
  return out;
}

ElementSpanLoad Loading::spanOn(int element) const {
  ElementSpanLoad q;
  const auto it = std::lower_bound(span_.begin(), span_.end(), element,
                                   [](const auto& entry, int e) { return entry.first < e; });
  if (it != span_.end() && it->first == element) q += it->second;
  for (const auto& [part, factor] : parts_) q += factor * part->spanOn(element);
  return q;
}

std::vector<int> Loading::loadedElements() const {
  std::vector<int> out;
  for (const auto& entry : span_) out.push_back(entry.first);
  for (const auto& part : parts_) {
    const std::vector<int> theirs = part.first->loadedElements();
    std::vector<int> merged;
    std::set_union(out.begin(), out.end(), theirs.begin(), theirs.end(),
                   std::back_inserter(merged));
    out.swap(merged);
  }
  return out;
}

}  // namespace beamrotor

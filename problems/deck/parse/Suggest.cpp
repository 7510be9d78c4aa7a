#include "problems/deck/parse/Suggest.hpp"

#include <algorithm>
#include <cctype>

namespace beamrotor {

int editDistance(std::string_view a, std::string_view b) {
  // One row of the dynamic-programming table at a time.
  std::vector<int> row(b.size() + 1);
  for (std::size_t j = 0; j <= b.size(); ++j) row[j] = int(j);
  for (std::size_t i = 1; i <= a.size(); ++i) {
    int diagonal = row[0];
    row[0] = int(i);
    for (std::size_t j = 1; j <= b.size(); ++j) {
      const int above = row[j];
      row[j] = std::min({row[j] + 1, row[j - 1] + 1, diagonal + (a[i - 1] == b[j - 1] ? 0 : 1)});
      diagonal = above;
    }
  }
  return row[b.size()];
}

namespace {

std::string lower(std::string_view s) {
  std::string out(s);
  for (char& c : out) c = char(std::tolower(static_cast<unsigned char>(c)));
  return out;
}

}  // namespace

std::string closestMatch(std::string_view word, const std::vector<std::string>& candidates,
                         int leastAllowed) {
  // Typos in very long words are not worth the time (and the fuzzer feeds long ones).
  constexpr std::size_t kLongest = 64;
  if (word.empty() || word.size() > kLongest) return {};
  const int allowed = std::max(leastAllowed, int(word.size()) / 3);
  std::string best;
  int bestDistance = allowed + 1;
  for (const std::string& c : candidates) {
    if (c.size() > kLongest) continue;
    const int d = lower(word) == lower(c) ? 0 : editDistance(word, c);
    if (d < bestDistance) {
      best = c;
      bestDistance = d;
    }
  }
  return best;
}

std::string didYouMean(std::string_view word, const std::vector<std::string>& candidates) {
  const std::string best = closestMatch(word, candidates);
  return best.empty() ? std::string{} : "; did you mean '" + best + "'?";
}

std::string joinNames(const std::vector<std::string>& names) {
  constexpr std::size_t kShown = 20;  // a message stays one readable line
  std::string out;
  for (std::size_t i = 0; i < names.size() && i < kShown; ++i)
    out += (out.empty() ? "" : ", ") + names[i];
  if (names.size() > kShown) out += ", ... (" + std::to_string(names.size()) + " in all)";
  return out.empty() ? "(none)" : out;
}

}  // namespace beamrotor

// "Did you mean ...?" for misspelt keys and names: the closest candidate by edit distance.
#pragma once

#include <string>
#include <string_view>
#include <vector>

namespace beamrotor {

/// Levenshtein distance (insertions, deletions, substitutions), case-sensitive.
int editDistance(std::string_view a, std::string_view b);

/// The candidate closest to `word` when it is close enough to be a plausible typo (distance at
/// most a third of the word's length, at least 1, or equal ignoring case; at least
/// `leastAllowed` when given, e.g. 2 for a short list of commands, where a swapped pair of
/// letters, "slove", costs 2 and still means one thing); empty otherwise.
std::string closestMatch(std::string_view word, const std::vector<std::string>& candidates,
                         int leastAllowed = 1);

/// "; did you mean 'length'?" or empty, ready to append to a message.
std::string didYouMean(std::string_view word, const std::vector<std::string>& candidates);

/// "a, b, c" for messages listing what is allowed; a long list shows its first 20 names and
/// the count.
std::string joinNames(const std::vector<std::string>& names);

}  // namespace beamrotor

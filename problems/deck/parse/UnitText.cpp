// Unit texts (see UnitText.hpp).
#include "problems/deck/parse/UnitText.hpp"

#include <charconv>
#include <cmath>
#include <string>

namespace beamrotor {

namespace {

/// A word "kN", "s^2" or "1" into size; false when it is none of them.
bool multiplyByWord(std::string_view word, int sign, UnitSize& size) {
  int exponent = 1;
  if (const auto caret = word.find('^'); caret != std::string_view::npos) {
    const std::string_view digits = word.substr(caret + 1);
    const auto [end, error] = std::from_chars(digits.data(), digits.data() + digits.size(), exponent);
    if (error != std::errc() || end != digits.data() + digits.size() || exponent == 0) return false;
    word = word.substr(0, caret);
  }
  if (word == "1") return true;
  const std::optional<Unit> unit = findUnit(std::string(word));
  if (!unit) return false;
  const int power = sign * exponent;
  size.si *= std::pow(unit->si, power);
  for (std::size_t i = 0; i < size.dimension.exponents.size(); ++i)
    size.dimension.exponents[i] += power * unit->dimension.exponents[i];
  return true;
}

}  // namespace

std::optional<UnitSize> unitSize(std::string_view text) {
  UnitSize size;
  int sign = 1;  // after the '/': dividing
  std::size_t i = 0;
  while (i < text.size()) {
    const char c = text[i];
    if (c == ' ' || c == '(' || c == ')') {  // "m/(rad s)": the parentheses group the divisor
      ++i;
      continue;
    }
    if (c == '/') {
      if (sign < 0) return std::nullopt;  // one '/' only: "a/b/c" reads two ways
      sign = -1;
      ++i;
      continue;
    }
    const std::size_t end = text.find_first_of(" /()", i);
    const std::string_view word = text.substr(i, end == std::string_view::npos ? end : end - i);
    if (!multiplyByWord(word, sign, size)) return std::nullopt;
    i = end == std::string_view::npos ? text.size() : end;
  }
  return size;
}

}  // namespace beamrotor

#include "problems/deck/parse/UnitSyntax.hpp"

#include <cctype>
#include <cstdlib>
#include <stdexcept>
#include <vector>

#include "problems/deck/parse/Suggest.hpp"
#include "problems/deck/parse/Units.hpp"

namespace beamrotor {

namespace {

bool isDigit(char c) {
  return std::isdigit(static_cast<unsigned char>(c)) != 0;
}
bool startsWord(char c) {
  return std::isalpha(static_cast<unsigned char>(c)) != 0 || c == '_';
}
bool inWord(char c) {
  return std::isalnum(static_cast<unsigned char>(c)) != 0 || c == '_';
}

/// The end of the number literal starting at i: digits, a point, digits, an exponent.
std::size_t numberEnd(const std::string& s, std::size_t i) {
  while (i < s.size() && (isDigit(s[i]) || s[i] == '.')) ++i;
  if (i < s.size() && (s[i] == 'e' || s[i] == 'E')) {
    std::size_t j = i + 1;
    if (j < s.size() && (s[j] == '+' || s[j] == '-')) ++j;
    if (j < s.size() && isDigit(s[j])) {
      i = j;
      while (i < s.size() && isDigit(s[i])) ++i;
    }
  }
  return i;
}

std::vector<std::string> unitNames() {
  std::vector<std::string> names;
  for (const Unit& u : units()) names.emplace_back(u.name);
  return names;
}

}  // namespace

std::string writeUnitProducts(const std::string& text,
                              const std::function<bool(const std::string&)>& isName) {
  enum class Last { other, number, word, close };
  Last last = Last::other;
  std::string out;
  out.reserve(text.size() + 8);
  std::size_t i = 0;
  while (i < text.size()) {
    const char c = text[i];
    if (c == ' ' || c == '\t') {
      out += c;
      ++i;
      continue;
    }
    if (isDigit(c) || (c == '.' && i + 1 < text.size() && isDigit(text[i + 1]))) {
      const std::size_t end = numberEnd(text, i);
      out.append(text, i, end - i);
      i = end;
      last = Last::number;
      continue;
    }
    if (startsWord(c)) {
      std::size_t end = i;
      while (end < text.size() && inWord(text[end])) ++end;
      const std::string word = text.substr(i, end - i);
      std::size_t next = end;
      while (next < text.size() && (text[next] == ' ' || text[next] == '\t')) ++next;
      const bool call = next < text.size() && text[next] == '(';
      if (last != Last::other && !call) {
        const bool unit = findUnit(word).has_value();
        if (unit && !isName(word)) {
          out += '*';
        } else if (last == Last::number && unit) {
          throw std::invalid_argument(
              "'" + word + "' after a number is the deck's own value '" + word +
              "' here, not the unit (a parameter of that name hides it); write '*" + word +
              "' to multiply by the value, or rename it");
        } else if (last == Last::number && !isName(word)) {
          throw std::invalid_argument("unknown unit '" + word + "'" +
                                      didYouMean(word, unitNames()) +
                                      " (units: " + joinNames(unitNames()) + ")");
        }
      }
      out += word;
      i = end;
      last = Last::word;
      continue;
    }
    out += c;
    ++i;
    last = c == ')' ? Last::close : Last::other;
  }
  return out;
}

std::string zerosAsOnes(const std::string& text) {
  std::string out;
  out.reserve(text.size());
  std::size_t i = 0;
  while (i < text.size()) {
    const char c = text[i];
    std::size_t end = i + 1;
    if (startsWord(c)) {
      while (end < text.size() && inWord(text[end])) ++end;  // a name, digits and all
      out.append(text, i, end - i);
    } else if (isDigit(c) || (c == '.' && i + 1 < text.size() && isDigit(text[i + 1]))) {
      end = numberEnd(text, i);
      const std::string literal = text.substr(i, end - i);
      out += std::strtod(literal.c_str(), nullptr) == 0 ? "1" : literal;
    } else {
      out += c;
    }
    i = end;
  }
  return out;
}

}  // namespace beamrotor

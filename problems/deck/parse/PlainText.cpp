// Plain text (see PlainText.hpp).
#include "problems/deck/parse/PlainText.hpp"

#include <algorithm>
#include <cstdio>

namespace beamrotor {

namespace {

/// The code point of a valid sequence of length n at text[i].
char32_t codePoint(std::string_view text, std::size_t i, std::size_t n) {
  const auto byte = [&](std::size_t k) { return char32_t(static_cast<unsigned char>(text[k])); };
  if (n == 1) return byte(i);
  char32_t c = byte(i) & (0x7F >> n);
  for (std::size_t k = 1; k < n; ++k) c = (c << 6) | (byte(i + k) & 0x3F);
  return c;
}

bool isControl(char32_t c) {
  return c < 0x20 || (c >= 0x7F && c <= 0x9F) || c == 0x2028 || c == 0x2029;
}

/// Length of the character at text[i] when it is plain text, else 0.
std::size_t plainLength(std::string_view text, std::size_t i, std::string_view allowedControls) {
  const std::size_t n = utf8SequenceLength(text, i);
  if (n == 0) return 0;
  const char32_t c = codePoint(text, i, n);
  if (isControl(c) && !(n == 1 && allowedControls.find(text[i]) != std::string_view::npos))
    return 0;
  return n;
}

}  // namespace

std::size_t utf8SequenceLength(std::string_view text, std::size_t i) {
  if (i >= text.size()) return 0;
  const auto byte = [&](std::size_t k) { return static_cast<unsigned char>(text[k]); };
  const unsigned char lead = byte(i);
  const std::size_t n = lead < 0x80           ? 1
                        : (lead >> 5) == 0x6  ? 2
                        : (lead >> 4) == 0xE  ? 3
                        : (lead >> 3) == 0x1E ? 4
                                              : 0;
  if (n == 0 || i + n > text.size()) return 0;
  for (std::size_t k = 1; k < n; ++k)
    if ((byte(i + k) & 0xC0) != 0x80) return 0;
  const char32_t c = codePoint(text, i, n);
  constexpr char32_t kSmallest[] = {0, 0, 0x80, 0x800, 0x10000};  // below: overlong
  if (c < kSmallest[n] || (c >= 0xD800 && c <= 0xDFFF) || c > 0x10FFFF) return 0;
  return n;
}

std::optional<std::size_t> firstNonPlain(std::string_view text, std::string_view allowedControls) {
  for (std::size_t i = 0; i < text.size();) {
    const std::size_t n = plainLength(text, i, allowedControls);
    if (n == 0) return i;
    i += n;
  }
  return std::nullopt;
}

std::string describeNonPlain(std::string_view text, std::size_t offset) {
  if (offset >= text.size()) return "the end of the text";
  const unsigned char c = static_cast<unsigned char>(text[offset]);
  char code[8];
  std::snprintf(code, sizeof code, "0x%02X", unsigned(c));
  const std::size_t n = utf8SequenceLength(text, offset);
  const std::string what = n == 0      ? " (not valid UTF-8)"
                           : c == '\n' ? " (a line break)"
                           : c == '\r' ? " (a carriage return)"
                           : c == '\t' ? " (a tab)"
                           : c == 0    ? " (a NUL byte)"
                           : n == 1    ? " (a control character)"
                                       : " (a control character or line separator)";
  return std::string("byte ") + code + what;
}

std::string plainText(std::string_view text) {
  std::string out;
  out.reserve(text.size());
  for (std::size_t i = 0; i < text.size();) {
    const std::size_t n = plainLength(text, i, {});
    if (n == 0) {
      out += '?';
      i += std::max<std::size_t>(1, utf8SequenceLength(text, i));
    } else {
      out.append(text.substr(i, n));
      i += n;
    }
  }
  return out;
}

}  // namespace beamrotor

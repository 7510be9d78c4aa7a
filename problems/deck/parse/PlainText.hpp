// What counts as plain text wherever deck text travels (titles, names, labels, units, file
// names): valid UTF-8 without control characters. The deck reader refuses anything else at the
// line that holds it; the writers make any text plain before it reaches a file or a script, so
// that no byte of it can end a line or a string there.
#pragma once

#include <cstddef>
#include <optional>
#include <string>
#include <string_view>

namespace beamrotor {

/// Length (1 to 4) of the UTF-8 sequence starting at text[i], or 0 when it is not valid UTF-8:
/// a stray continuation byte, a truncated or overlong sequence, a surrogate (U+D800..DFFF) or
/// a code point beyond U+10FFFF.
std::size_t utf8SequenceLength(std::string_view text, std::size_t i);

/// The offset of the first byte that is not plain text: invalid UTF-8, or a control character
/// (U+0000..001F, U+007F..009F, the line and paragraph separators U+2028, U+2029) other than
/// those listed in `allowedControls` (e.g. "\n\r\t" for a whole file). nullopt when all is
/// plain.
std::optional<std::size_t> firstNonPlain(std::string_view text,
                                         std::string_view allowedControls = {});

/// "byte 0x0A (a line break)": what lies at `offset`, for messages.
std::string describeNonPlain(std::string_view text, std::size_t offset);

/// text with every character that is not plain (see firstNonPlain) replaced by '?'.
std::string plainText(std::string_view text);

}  // namespace beamrotor

// Plain text (problems/deck/parse/PlainText.hpp): the one definition of text that may travel from a
// deck into messages, tables and chart scripts.
#include <doctest/doctest.h>

#include "problems/deck/parse/PlainText.hpp"

using namespace beamrotor;

TEST_SUITE("plain text") {
  TEST_CASE("UTF-8 sequences: valid ones by length, every kind of invalid one refused") {
    CHECK(utf8SequenceLength("a", 0) == 1);
    CHECK(utf8SequenceLength("\xC3\xA9", 0) == 2);          // é
    CHECK(utf8SequenceLength("\xE2\x82\xAC", 0) == 3);      // €
    CHECK(utf8SequenceLength("\xF0\x9F\x98\x80", 0) == 4);  // U+1F600
    CHECK(utf8SequenceLength("\xF4\x8F\xBF\xBF", 0) == 4);  // U+10FFFF, the last
    CHECK(utf8SequenceLength("\x80", 0) == 0);              // a continuation byte alone
    CHECK(utf8SequenceLength("\xC3", 0) == 0);              // truncated
    CHECK(utf8SequenceLength("\xE2\x82", 0) == 0);
    CHECK(utf8SequenceLength("\xC0\xAF", 0) == 0);          // overlong '/'
    CHECK(utf8SequenceLength("\xE0\x80\xAF", 0) == 0);      // overlong '/'
    CHECK(utf8SequenceLength("\xF0\x80\x80\xAF", 0) == 0);  // overlong '/'
    CHECK(utf8SequenceLength("\xED\xA0\x80", 0) == 0);      // surrogate U+D800
    CHECK(utf8SequenceLength("\xF4\x90\x80\x80", 0) == 0);  // U+110000
    CHECK(utf8SequenceLength("\xF8\x88\x80\x80\x80", 0) == 0);
    CHECK(utf8SequenceLength("\xC3\x41", 0) == 0);  // second byte not a continuation
  }

  TEST_CASE("control characters and line separators are not plain; others are") {
    CHECK_FALSE(firstNonPlain("Cantilever, kN·m, µm, θ_z, 'quoted' `ticks` | < @ \\"));
    for (const std::string& bad :
         {std::string("a\nb"), std::string("a\rb"), std::string("a\tb"), std::string("a\0b", 3),
          std::string("a\x1b"), std::string("a\x7f"), std::string("a\xC2\x85"),
          std::string("a\xC2\x9B"), std::string("a\xE2\x80\xA8"), std::string("a\xE2\x80\xA9"),
          std::string("a\xFF")}) {
      CAPTURE(bad);
      CHECK(firstNonPlain(bad) == std::optional<std::size_t>(1));
      CHECK(plainText(bad).find_first_of(std::string("\n\r\t\0\x1b\x7f", 6)) == std::string::npos);
      CHECK_FALSE(firstNonPlain(plainText(bad)));
    }
    // A whole file may have line breaks and tabs, nothing else.
    CHECK_FALSE(firstNonPlain("a: 1\r\n\tb: 2\n", "\n\r\t"));
    CHECK(firstNonPlain("a: 1\n\x0b", "\n\r\t") == std::optional<std::size_t>(5));
  }

  TEST_CASE("plainText replaces each bad character by one '?' and keeps the rest") {
    CHECK(plainText("a\nb") == "a?b");
    CHECK(plainText("x\xE2\x80\xA8y") == "x?y");  // one character, three bytes
    CHECK(plainText("\xFF\xFE") == "??");
    CHECK(plainText("θ = 0.5") == "θ = 0.5");
    CHECK(describeNonPlain("a\nb", 1) == "byte 0x0A (a line break)");
    CHECK(describeNonPlain("a\xFF", 1) == "byte 0xFF (not valid UTF-8)");
  }
}

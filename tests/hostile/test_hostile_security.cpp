// Hostile suite, class 1: nothing from a deck is ever executed. Deck text reaches gnuplot
// scripts (titles, units, check names, the deck's file name); a line break inside it would end
// the script line and let the next be any command. Text that could do so is refused at the
// deck line that holds it (exit 2); any other text is drawn as it is, inert.
#include <doctest/doctest.h>

#include <fstream>

#include "tests/hostile/HostileSupport.hpp"

using namespace beamrotor::test;
namespace fs = std::filesystem;

namespace {

/// A payload written inside a YAML double-quoted scalar (escapes decoded by YAML).
struct Payload {
  std::string what;
  std::string yaml;
};

/// Characters that end or break a script line, each followed by a command where it fits.
const std::vector<Payload> kLineBreakers{
    {"line feed", R"(N\nsystem \"touch ../canary\")"},
    {"carriage return", R"(N\rsystem \"touch ../canary\")"},
    {"line feed then !", R"(N\n!touch ../canary)"},
    {"vertical tab", R"(N\vx)"},
    {"form feed", R"(N\fx)"},
    {"NUL", R"(N\0x)"},
    {"escape", R"(N\ex)"},
    {"delete", R"(N\x7Fx)"},
    {"next line U+0085", R"(N\Nx)"},
    {"line separator U+2028", R"(N\Lx)"},
    {"paragraph separator U+2029", R"(N\Px)"},
    {"tab", R"(N\tx)"},
    {"C1 control U+009B", R"(N\x9Bx)"},
};

/// The three free-text fields a deck has, and where an error about each points.
struct TextField {
  std::string name;
  std::string path;  ///< as a regex
  std::function<std::string(const std::string&)> deck;
};

const std::vector<TextField> kTextFields{
    {"title", "title", [](const std::string& v) { return hostileBaseDeck(v); }},
    {"unit", R"(analyses\[1\]\.record\[1\]\.unit)",
     [](const std::string& v) { return hostileBaseDeck("Cantilever", v); }},
    {"check name", R"(checks\[0\]\.name)",
     [](const std::string& v) { return hostileBaseDeck("Cantilever", "N", v); }},
};

/// Printable text gnuplot would act on outside a single-quoted string: it is drawn as text.
const std::vector<std::string> kInertUnits{
    R"("`touch ../canary`")",
    R"("'; system 'touch ../canary'")",
    R"("!touch ../canary")",
    R"x("system(\"touch ../canary\")")x",
    R"("|touch ../canary")",
    R"("<touch ../canary")",
    R"("@cmd \\")",
    R"("N \\")",
    R"("{/Symbol m}m^2_x&{}~a\\")",
    R"("kN·m, µm, θ")",
};

}  // namespace

TEST_SUITE("hostile input: security") {
  TEST_CASE("a control character in deck text is refused at its line, whatever the field") {
    std::vector<HostileCase> cases;
    for (const TextField& field : kTextFields)
      for (const Payload& p : kLineBreakers)
        cases.push_back({field.name + ": " + p.what,
                         field.deck("\"" + p.yaml + "\""),
                         {"solve", "deck.yaml", "--out", "out"},
                         2,
                         atField(field.path) + "holds byte 0x[0-9A-F]{2} \\(",
                         {}});
    CHECK(runHostileCases(cases) == 39);
  }

  TEST_CASE("text that is not UTF-8 is refused: in the file, or made by a YAML escape") {
    std::vector<HostileCase> cases{
        {"a surrogate escape in a title",
         hostileBaseDeck(R"("a\uD800b")"),
         {"check", "deck.yaml"},
         2,
         R"(^deck\.yaml:1:\d+: )",
         {}},
        {"a byte 0xFF in a unit",
         hostileBaseDeck("Cantilever", "N\xFF"),
         {"check", "deck.yaml"},
         2,
         R"(^deck\.yaml:\d+:\d+: not a text deck: byte 0xFF \(not valid UTF-8\))",
         {}},
        {"an overlong encoding of '/' in a title",
         hostileBaseDeck("a\xC0\xAF"),
         {"check", "deck.yaml"},
         2,
         R"(^deck\.yaml:1:\d+: not a text deck: byte 0xC0 \(not valid UTF-8\))",
         {}},
        {"an encoded surrogate in a check name",
         hostileBaseDeck("Cantilever", "N", "c\xED\xA0\x80"),
         {"check", "deck.yaml"},
         2,
         R"(^deck\.yaml:\d+:\d+: not a text deck: byte 0xED)",
         {}},
        {"a code point beyond U+10FFFF",
         hostileBaseDeck("a\xF4\x90\x80\x80"),
         {"check", "deck.yaml"},
         2,
         R"(^deck\.yaml:1:\d+: not a text deck: byte 0xF4)",
         {}},
        {"a truncated sequence at the end of a title",
         hostileBaseDeck("\"a\xE2\x82\""),
         {"check", "deck.yaml"},
         2,
         R"(^deck\.yaml:1:\d+: not a text deck: byte 0xE2)",
         {}},
    };
    CHECK(runHostileCases(cases) == 6);
  }

  TEST_CASE("every other text reaches the charts inert (real gnuplot)") {
    // All payloads in one deck (one history each), so that gnuplot runs once per chart.
    std::string deck =
        hostileBaseDeck(R"("t `touch ../canary` '|<@")", "N", R"("c`touch ../canary`'\\")");
    std::string histories;
    for (std::size_t i = 0; i < kInertUnits.size(); ++i)
      histories += "      - {name: h" + std::to_string(i) + ", value: tip*" + std::to_string(i) +
                   ", unit: " + kInertUnits[i] + "}\n";
    deck.insert(deck.find("checks:"), histories);
    HostileCase c{"inert units, title and check name",
                  deck,
                  {"solve", "deck.yaml", "--out", "out"},
                  0,
                  "",
                  {"out"}};
    c.charts = true;
    const ProcessResult r = runHostileCase(c);
    CHECK(r.err.find("warning") == std::string::npos);  // gnuplot drew every chart
    CHECK(kInertUnits.size() == 10);
  }

  TEST_CASE("a deck's file name reaches the chart captions inert (real gnuplot)") {
    const std::string name = "d\n!touch canary\n`touch canary`'|<.yaml";
    HostileCase c{
        "file name with line breaks and quotes",
        "",
        {"solve", name, "--out", "out"},
        0,
        "",
        {"out"},
        [&](const fs::path& sandbox) { std::ofstream(sandbox / name) << hostileBaseDeck(); }};
    c.charts = true;
    const ProcessResult r = runHostileCase(c);
    CHECK(r.err.find("warning") == std::string::npos);
  }

  TEST_CASE("names that would be file names are plain words; a hostile one is refused") {
    const auto withAnalysis = [](const std::string& name) {
      std::string deck = hostileBaseDeck();
      const std::string from = "name: bend";
      return deck.replace(deck.find(from), from.size(), "name: " + name);
    };
    std::vector<HostileCase> cases;
    for (const char* name : {R"("../escape")", R"("/tmp/abs")", R"("|cmd")", R"("<cmd")",
                             R"("a b")", R"("x;y")", R"("")"})
      cases.push_back({std::string("analysis named ") + name,
                       withAnalysis(name),
                       {"solve", "deck.yaml", "--out", "out"},
                       2,
                       atField(R"(analyses\[0\]\.name)") + "expected a name",
                       {}});
    CHECK(runHostileCases(cases) == 7);
  }
}

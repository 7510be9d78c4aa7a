// Hostile suite, class 5: every failure a clear error, never a crash, a hang or a wrong
// answer. Special files as decks, overflow in time, meshes that build nothing, contacts that
// never act, checks that compute no number, command-line values out of range, decks too big
// for the bounds or the memory, and the report outside the source tree.
#include <doctest/doctest.h>
#include <sys/stat.h>

#include <fstream>

#include "tests/hostile/HostileSupport.hpp"

using namespace beamrotor::test;
namespace fs = std::filesystem;

namespace {

/// The base deck with `from` replaced by `to` (first occurrence).
std::string edited(const std::string& from, const std::string& to,
                   std::string deck = hostileBaseDeck()) {
  const std::size_t at = deck.find(from);
  REQUIRE(at != std::string::npos);
  return deck.replace(at, from.size(), to);
}

const std::vector<std::string> kCheck{"check", "deck.yaml"};
const std::vector<std::string> kSolve{"solve", "deck.yaml", "--out", "out"};

std::vector<std::string> plus(std::vector<std::string> a, const std::vector<std::string>& b) {
  a.insert(a.end(), b.begin(), b.end());
  return a;
}

/// A two-spring body whose modes decouple: its first mode's node lies at infinity.
const std::string kDecoupledBody = std::string(kHostileBeam) + R"(points:
  - {name: A, at: 0.2}
  - {name: B, at: 0.8}
springs:
  - {name: kA, at: A, dof: uy, k: 1e6}
  - {name: kB, at: B, dof: uy, k: 1e6}
analyses:
  - {type: rigid-body, bearings: [A, B]}
checks:
  - {name: node one, quantity: rigid_body n1, reference: 1, tolerance: 0.1}
)";

std::string manyItems(const std::string& head, const std::string& item, int count) {
  std::string text = head;
  for (int i = 0; i < count; ++i) text += "  " + edited("#", std::to_string(i), item) + "\n";
  return text;
}

}  // namespace

TEST_SUITE("hostile input: faults") {
  TEST_CASE("anything but a regular file as the deck is refused at once") {
    std::vector<HostileCase> cases{
        {"a FIFO with no writer",
         "",
         kCheck,
         2,
         "^deck\\.yaml: is not a regular file",
         {},
         [](const fs::path& s) { ::mkfifo((s / "deck.yaml").c_str(), 0644); }},
        {"a link to a FIFO",
         "",
         kCheck,
         2,
         "^deck\\.yaml: is not a regular file",
         {},
         [](const fs::path& s) {
           ::mkfifo((s / "fifo").c_str(), 0644);
           fs::create_symlink(s / "fifo", s / "deck.yaml");
         }},
        {"/dev/zero", "", {"check", "/dev/zero"}, 2, "^/dev/zero: is not a regular file", {}},
        {"/dev/null", "", {"check", "/dev/null"}, 2, "^/dev/null: is not a regular file", {}},
        {"a directory", "", {"check", "."}, 2, "^\\.: is a directory, not a deck file", {}},
        {"a missing file", "", {"check", "nothing.yaml"}, 2, "^nothing\\.yaml: cannot open", {}},
        {"an empty file",
         "",
         kCheck,
         2,
         "^deck\\.yaml:1:1: the deck is empty",
         {},
         [](const fs::path& s) { std::ofstream(s / "deck.yaml"); }},
        {"a file of 17 MB",
         std::string(17 << 20, '#'),
         kCheck,
         2,
         "^deck\\.yaml: the file is \\d+ bytes; a deck may have at most",
         {}},
    };
    cases[0].process = cases[1].process = true;  // a hang must end the run, not the tests
    CHECK(runHostileCases(cases) == 8);
  }

  TEST_CASE("overflow in time stops the run, naming the step") {
    const std::string overflowed =
        atField(R"(analyses\[1\])") +
        R"(the (displacement|velocity|acceleration|energy) overflowed at step \d+ \(t = [0-9.e-]+ s\))";
    std::vector<HostileCase> cases{
        {"an absurd load",
         edited("record:", "loads:\n      - {at: end, dof: uy, value: 1e300}\n    record:"),
         kSolve,
         1,
         overflowed,
         {}},
        {"an absurd load, check",
         edited("record:", "loads:\n      - {at: end, dof: uy, value: 1e300}\n    record:"),
         kCheck,
         1,
         overflowed,
         {}},
        {"an absurd initial velocity",
         edited("record:", "initial:\n      - {at: end, dof: uy, v: 1e300}\n    record:"),
         kSolve,
         1,
         overflowed,
         {}},
        {"a load growing without bound",
         edited("record:",
                "loads:\n      - {at: end, dof: uy, value: 1e150*exp(1e5*t)}\n    record:"),
         kSolve,
         1,
         "^deck\\.yaml:\\d+:\\d+: analyses\\[1\\]",
         {}},
    };
    CHECK(runHostileCases(cases) == 4);
  }

  TEST_CASE("a mesh request that builds nothing, and a contact that never acts, are bad input") {
    const std::string tiny =
        "  - {name: a, length: 1, section: bar, elements: 4}\n"
        "  - {name: tiny, length: 1e-14, section: bar, elements: 3}";
    const std::string contact = "contacts:\n  - {name: stop, at: WHERE, dof: DOF, min: 0}\nloads:";
    // Statics only: with a transient analysis a contact is a stop in time, which needs
    // lumped masses.
    std::string statics = edited("segments:", "points:\n  - {name: root, at: 0}\nsegments:");
    statics.erase(statics.find("  - type: transient"),
                  statics.find("checks:") - statics.find("  - type: transient"));
    const auto withContact = [&](const std::string& where, const std::string& dof) {
      return edited("loads:", edited("DOF", dof, edited("WHERE", where, contact)), statics);
    };
    std::vector<HostileCase> cases{
        {"a segment within the geometric tolerance",
         edited("  - {name: a, length: 1, section: bar, elements: 4}", tiny),
         kCheck,
         2,
         atField(R"(segments\[1\]\.length)") +
             "segment 'tiny' is 1e-14 m long, within the geometric tolerance",
         {}},
        {"an unnamed one on a long line",
         edited("  - {name: a, length: 1, section: bar, elements: 4}",
                "  - {length: 1e6, section: bar, elements: 4}\n  - {length: 1e-7, section: bar, "
                "size: 1}"),
         kCheck,
         2,
         atField(R"(segments\[1\]\.length)") + "segment 2 is 1e-07 m long",
         {}},
        {"a short segment above the tolerance is fine",
         edited("  - {name: a, length: 1, section: bar, elements: 4}",
                "  - {name: a, length: 1, section: bar, elements: 4}\n  - {name: b, length: 1e-4, "
                "section: bar, elements: 1}"),
         kCheck,
         0,
         "",
         {}},
        {"a contact on a clamped dof",
         withContact("start", "uy"),
         kCheck,
         2,
         atField(R"(contacts\[0\]\.dof)") + "uy at point 'start' is held by support 'left'",
         {}},
        {"a contact at another name of the support's place",
         withContact("root", "rz"),
         kCheck,
         2,
         atField(R"(contacts\[0\]\.dof)") + "rz at point 'root' is held by support 'left'",
         {}},
        {"a contact on a free dof is fine", withContact("end", "ux"), kCheck, 0, "", {}},
    };
    CHECK(runHostileCases(cases) == 6);
  }

  TEST_CASE("a check that computes no finite number fails, naming the check and the quantity") {
    std::vector<HostileCase> cases{
        {"check",
         kDecoupledBody,
         kCheck,
         1,
         R"(^deck\.yaml:\d+:\d+: checks\[0\]: check 'node one': n1 is infinite)",
         {}},
        {"solve",
         kDecoupledBody,
         kSolve,
         1,
         R"(^deck\.yaml:\d+:\d+: checks\[0\]: check 'node one')",
         {}},
        {"the accuracy search",
         kDecoupledBody + "accuracy: 0.01\n",
         kCheck,
         1,
         R"(^deck\.yaml:\d+:\d+: checks\[0\]: check 'node one')",
         {}},
    };
    CHECK(runHostileCases(cases) == 3);
  }

  TEST_CASE("command-line values out of range are bad input, naming the option") {
    const std::string deck = hostileBaseDeck("Cantilever") + "parameters: {P: 1000}\n";
    const auto set = [&](const std::string& value) { return plus(kCheck, {"--set", value}); };
    const auto sweep = [&](const std::string& value) { return plus(kCheck, {"--sweep", value}); };
    std::vector<HostileCase> cases{
        {"--set beyond a double", deck, set("P=1e400"), 2, R"(^deck\.yaml: --set P=1e400: )", {}},
        {"--set dividing by zero", deck, set("P=1/0"), 2, R"(^deck\.yaml: --set P=1/0: )", {}},
        {"--set NaN", deck, set("P=sqrt(-1)"), 2, R"(--set P=sqrt\(-1\): .*nan)", {}},
        {"--set nothing", deck, set("P="), 2, R"(--set P=: .*empty value)", {}},
        {"--set no name", deck, set("=1"), 2, R"(--set =1: '' is not a parameter name)", {}},
        {"--set no equals", deck, set("P"), 2, R"(--set P: expected NAME=VALUE)", {}},
        {"--set an unknown name", deck, set("Q=1"), 2, R"(no parameter 'Q' in this deck)", {}},
        {"--set a line break", deck, set("P=1\n2"), 2, R"(^deck\.yaml: --set P=1 2: )", {}},
        {"--set a long expression",
         deck,
         set("P=" + std::string(5000, '1')),
         2,
         "longer than 4096 characters",
         {}},
        {"--set deeply nested",
         deck,
         set("P=" + std::string(3000, '(') + "1" + std::string(3000, ')')),
         2,
         "--set P=",
         {}},
        {"--sweep too many steps", deck, sweep("P=0:1:1e9"), 2, "STEPS must be a whole number", {}},
        {"--sweep too far apart", deck, sweep("P=-1e308:1e308:2"), 2, "too far apart", {}},
        {"--sweep a NaN value", deck, sweep("P=1,sqrt(-1)"), 2, "nan", {}},
        {"--sweep an empty value", deck, sweep("P=1,,2"), 2, "empty value", {}},
        {"--sweep an unknown name", deck, sweep("Q=0:1:2"), 2, "no parameter 'Q'", {}},
        {"--sweep and --no-sweep",
         deck,
         plus(sweep("P=0:1:2"), {"--no-sweep"}),
         2,
         "contradicts --sweep",
         {}},
        {"--formulation unknown",
         deck,
         plus(kCheck, {"--formulation", "bernoulli"}),
         2,
         "--formulation bernoulli: expected euler-bernoulli, timoshenko",
         {}},
        {"converge --quantity with a line break",
         deck,
         {"converge", "deck.yaml", "--quantity", "displacement end\nuy", "--levels", "2"},
         2,
         "--quantity",
         {}},
        {"converge --levels beyond the element cap",
         deck,
         {"converge", "deck.yaml", "--levels", "16", "--quantity", "stress max", "--out", "out"},
         2,
         R"(--levels: the finest mesh would have \d+ elements, more than the 100000)",
         {}},
        {"bench --elements below the least",
         "",
         {"bench", "--kind", "planar", "--elements", "3"},
         2,
         "--elements",
         {}},
    };
    CHECK(runHostileCases(cases) == 20);
  }

  TEST_CASE("what must be bounded is bounded, with a clear error at the line") {
    std::string params = "parameters:\n";
    for (int i = 0; i <= 10000; ++i)
      params += "  p" + std::to_string(i) + ": " + std::to_string(i) + "\n";
    std::vector<HostileCase> cases{
        {"10001 parameters",
         params + hostileBaseDeck(),
         kCheck,
         2,
         atField(R"(parameters\.p10000)") + "a deck may have at most 10000 parameters",
         {}},
        {"1001 analyses",
         edited("analyses:", manyItems("analyses:\n", "- {type: static, name: s#}", 1001) + "#",
                hostileBaseDeck()),
         kCheck,
         2,
         atField(R"(analyses\[1000\])") + "a deck may have at most 1000 analyses",
         {}},
        {"1001 checks",
         hostileBaseDeck() +
             manyItems("",
                       "- {name: c#, quantity: displacement end uy, reference: 1, tolerance: 1}",
                       1001),
         kCheck,
         2,
         atField(R"(checks\[1000\])") + "a deck may have at most 1000 checks",
         {}},
        {"100001 elements",
         edited("elements: 4", "elements: 100001"),
         kCheck,
         2,
         atField(R"(segments\[0\]\.elements)") + "must lie between 1 and 100000",
         {}},
        {"an element size that would make 1e12 elements",
         edited("elements: 4", "size: 1e-12"),
         kCheck,
         2,
         atField(R"(segments\[0\])") + "the line would have more than 100000 elements",
         {}},
        {"1001 frames",
         edited("end: 0.004", "end: 0.004\n    frames: 1001"),
         kCheck,
         2,
         R"(^deck\.yaml:\d+:\d+: analyses\[1\]\.frames: )",
         {}},
        {"1e8 time steps",
         edited("dt: 0.001", "dt: 1e-10"),
         kCheck,
         2,
         R"(^deck\.yaml:\d+:\d+: analyses\[1\])",
         {}},
        {"101 modes",
         edited("  - {type: static, name: bend}", "  - {type: modal, name: vib, modes: 101}"),
         kCheck,
         2,
         atField(R"(analyses\[0\]\.modes)"),
         {}},
        {"a run that cannot fit in memory: refused with the estimate",
         edited("end: 0.004", "end: 0.004\n    frames: 1000",
                edited("elements: 4", "elements: 99990")) +
             "sweep: {parameter: P, from: 1, to: 1000, steps: 999}\nparameters: {P: 1}\n",
         kCheck,
         1,
         atField(R"(analyses\[1\])") +
             R"(this run needs about [0-9.]+ [GT]B \(1000 sweep values kept\) but [0-9.]+ [MG]B are available; the largest part is transient 'shake': 1000 frames of \d+ nodes)",
         {}},
    };
    CHECK(runHostileCases(cases) == 9);
  }

  TEST_CASE("beamrotor report outside the source tree says what it needs") {
    std::vector<HostileCase> cases{
        {"no problems/ here",
         "",
         {"report", "--out", "site"},
         2,
         R"(^beamrotor report: the report checks the shipped decks \(problems/\*\.yaml of the beamrotor source tree\), but 'problems' holds none: run it from the source directory, or give --decks DIR)",
         {}},
        {"--decks naming an empty directory",
         "",
         {"report", "--decks", "empty", "--out", "site"},
         2,
         "'empty' holds none",
         {},
         [](const fs::path& s) { fs::create_directories(s / "empty"); }},
    };
    CHECK(runHostileCases(cases) == 2);
  }
}

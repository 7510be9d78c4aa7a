// Hostile suite, classes 2 and 3: no file beamrotor did not write is ever deleted or
// overwritten, whatever --out, --export-matrices, --export or --json point at, and a write that
// fails ends with a non-zero exit naming the file.
#include <doctest/doctest.h>

#include <fstream>

#include "problems/output/files/AtomicDirectory.hpp"
#include "tests/hostile/HostileSupport.hpp"

using namespace beamrotor;
using namespace beamrotor::test;
namespace fs = std::filesystem;

namespace {

/// A directory of someone else's files, `name` in the sandbox.
std::function<void(const fs::path&)> foreignDirectory(const std::string& name) {
  return [name](const fs::path& sandbox) {
    fs::create_directories(sandbox / name / "chapters");
    std::ofstream(sandbox / name / "thesis.tex") << "precious";
    std::ofstream(sandbox / name / "chapters" / "one.tex") << "also precious";
  };
}

/// A results directory as beamrotor writes it, plus `extra` (a file beamrotor did not write).
std::function<void(const fs::path&)> resultsWith(const std::string& extra) {
  return [extra](const fs::path& sandbox) {
    fs::create_directories(sandbox / "out");
    std::ofstream(sandbox / "out" / "results.json") << "{}";
    std::ofstream(sandbox / "out" / kMarkerFile)
        << "# beamrotor results: the next run replaces this directory unless it holds anything "
           "not listed here\nresults.json\n";
    if (!extra.empty()) std::ofstream(sandbox / "out" / extra) << "mine";
  };
}

const std::string kRefused = R"(refusing to replace '[^']*': )";

}  // namespace

TEST_SUITE("hostile input: data") {
  TEST_CASE("--out never replaces what beamrotor did not write") {
    const std::string deck = hostileBaseDeck();
    const std::vector<std::string> solve{"solve", "deck.yaml", "--out"};
    const auto with = [&](std::vector<std::string> args, std::string extra) {
      args.push_back(std::move(extra));
      return args;
    };
    std::vector<HostileCase> cases{
        {"a directory of unrelated files",
         deck,
         with(solve, "thesis"),
         1,
         "^thesis: cannot write the results: " + kRefused + "beamrotor did not write it",
         {},
         foreignDirectory("thesis")},
        {"the deck's own directory, by absolute path",
         deck,
         with(solve, "{sandbox}"),
         1,
         kRefused + "beamrotor did not write it.*choose another output directory with --out DIR",
         {}},
        {"the deck's own directory, as ./",
         deck,
         with(solve, "./"),
         1,
         "must name a directory",
         {}},
        {"the parent directory", deck, with(solve, ".."), 1, "must name a directory", {}},
        {"the root directory", deck, with(solve, "/"), 1, "must name a directory", {}},
        {"the deck file itself",
         deck,
         with(solve, "deck.yaml"),
         1,
         "'deck.yaml': it exists and is not a directory",
         {}},
        {"a path under the deck file",
         deck,
         with(solve, "deck.yaml/out"),
         1,
         "cannot write the results",
         {}},
        {"results holding the deck copied into them",
         deck,
         with(solve, "out"),
         1,
         kRefused + "it holds 'deck.yaml', which beamrotor did not write",
         {},
         [](const fs::path& s) {
           resultsWith("")(s);
           fs::copy_file(s / "deck.yaml", s / "out" / "deck.yaml");
         }},
        {"results with notes added",
         deck,
         with(solve, "out"),
         1,
         kRefused + "it holds 'notes.txt'",
         {},
         resultsWith("notes.txt")},
        {"results of an older beamrotor (no marker)",
         deck,
         with(solve, "out"),
         1,
         kRefused + "beamrotor did not write it",
         {},
         [](const fs::path& s) {
           fs::create_directories(s / "out");
           std::ofstream(s / "out" / "results.json") << "{}";
         }},
        {"a symbolic link to a directory",
         deck,
         with(solve, "link"),
         1,
         "'link': it exists and is not a directory",
         {},
         [](const fs::path& s) {
           foreignDirectory("thesis")(s);
           fs::create_directory_symlink(s / "thesis", s / "link");
         }},
        {"a marked directory of ours: replaced",
         deck,
         with(solve, "out"),
         0,
         "",
         {"out"},
         resultsWith("")},
        {"an empty directory: filled",
         deck,
         with(solve, "out"),
         0,
         "",
         {"out"},
         [](const fs::path& s) { fs::create_directories(s / "out"); }},
        {"a new nested path: created", deck, with(solve, "out/a/b"), 0, "", {"out"}},
    };
    CHECK(runHostileCases(cases) == 14);
  }

  TEST_CASE("exported matrices and other commands' directories follow the same rule") {
    const std::string deck = hostileBaseDeck();
    std::vector<HostileCase> cases{
        {"--export-matrices into a directory of unrelated files",
         deck,
         {"solve", "deck.yaml", "--out", "out", "--export-matrices=thesis"},
         1,
         kRefused + "beamrotor did not write it",
         {"out"},
         foreignDirectory("thesis")},
        {"--export-matrices inside the results: replaced with them",
         deck,
         {"solve", "deck.yaml", "--out", "out", "--export-matrices=out/m"},
         0,
         "",
         {"out"},
         resultsWith("")},
        {"bench --export into a directory of unrelated files",
         "",
         {"bench", "--kind", "planar", "--elements", "10", "--modes", "0", "--repeat", "1",
          "--export", "thesis"},
         1,
         "^beamrotor bench: " + kRefused,
         {},
         foreignDirectory("thesis")},
        {"converge --out into a directory of unrelated files",
         deck,
         {"converge", "deck.yaml", "--levels", "3", "--out", "thesis"},
         1,
         "^thesis: cannot write the results: " + kRefused,
         {},
         foreignDirectory("thesis")},
        {"report --out over someone's index.html",
         "",
         {"report", "--decks", "decks", "--out", "site"},
         2,
         "^beamrotor report: refusing to replace 'site/index.html'",
         {},
         [](const fs::path& s) {
           fs::create_directories(s / "decks");
           std::ofstream(s / "decks" / "deck.yaml") << hostileBaseDeck();
           fs::create_directories(s / "site");
           std::ofstream(s / "site" / "index.html") << "<p>my page</p>";
         }},
    };
    CHECK(runHostileCases(cases) == 5);
  }

  TEST_CASE("a write that fails ends non-zero, naming the file; nothing is left half-written") {
    const std::string deck = hostileBaseDeck();
    std::vector<HostileCase> cases{
        {"bench --json onto a full device",
         "",
         {"bench", "--kind", "planar", "--elements", "10", "--modes", "0", "--repeat", "1",
          "--json", "/dev/full"},
         1,
         "^beamrotor bench: cannot write /dev/full: No space left on device",
         {}},
        {"bench --json into a missing directory",
         "",
         {"bench", "--kind", "planar", "--elements", "10", "--modes", "0", "--repeat", "1",
          "--json", "missing/b.json"},
         1,
         "^beamrotor bench: cannot write missing/b.json",
         {}},
        {"bench --json over an earlier file: replaced whole",
         "",
         {"bench", "--kind", "planar", "--elements", "10", "--modes", "0", "--repeat", "1",
          "--json", "b.json"},
         0,
         "",
         {"b.json"},
         [](const fs::path& s) { std::ofstream(s / "b.json") << "earlier"; }},
        {"--out under a device",
         deck,
         {"solve", "deck.yaml", "--out", "/dev/full/out"},
         1,
         "^/dev/full/out: cannot write the results: ",
         {}},
        {"--export-matrices under a device",
         deck,
         {"solve", "deck.yaml", "--out", "out", "--export-matrices=/dev/full/m"},
         1,
         "cannot write the results: ",
         {"out"}},
    };
    CHECK(runHostileCases(cases) == 5);
  }
}

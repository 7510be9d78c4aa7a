// The deck's tree (problems/deck/parse/DeckTree.hpp), copied once from yaml-cpp's and walked by every
// reading: aliases read as the values they name, an alias that expands without end is refused
// with a place, and maps with a key twice or a key that is not a word are refused as before,
// at the offending key.
#include <doctest/doctest.h>

#include <string>

#include "problems/deck/parse/DeckError.hpp"
#include "problems/deck/parse/DeckSource.hpp"
#include "problems/deck/parse/DeckTree.hpp"
#include "problems/run/Study.hpp"
#include "tests/problems/DeckTestSupport.hpp"

using namespace beamrotor;
using namespace beamrotor::test;

namespace {

/// A beam pinned at both ends under a uniform load q = 5 kN/m over L = 2 m, the supports'
/// fixed dofs given as `leftFix` and `rightFix` (YAML text: a list, an anchor, an alias).
std::string treeTestBeam(const std::string& leftFix, const std::string& rightFix) {
  return "title: tree test beam\n"
         "model: {dimension: planar, formulation: euler-bernoulli}\n"
         "materials: [{name: steel, E: 210e9, nu: 0.3, rho: 7850}]\n"
         "sections: [{name: bar, shape: rectangle, b: 0.04, h: 0.06}]\n"
         "segments: [{length: 2.0, section: bar, elements: 4}]\n"
         "supports:\n"
         "  - {name: left, at: start, fix: " + leftFix + "}\n"
         "  - {name: right, at: end, fix: " + rightFix + "}\n"
         "loads: [{type: distributed, qy: -5000}]\n"
         "analyses: [{type: static}]\n";
}

}  // namespace

TEST_SUITE("deck tree") {
  TEST_CASE("an alias reads as the value it names") {
    const Study plain = solveDeckText(treeTestBeam("[ux, uy]", "[ux, uy]"), "plain.yaml");
    const Study aliased = solveDeckText(treeTestBeam("&held [ux, uy]", "*held"), "aliased.yaml");
    // Each support carries half of q L = 10 kN (no axial load, so the pinned span's transverse
    // reactions are the simply supported ones; exact up to the solve's round-off), and the
    // alias changes nothing, bit for bit.
    for (const Study* s : {&plain, &aliased})
      for (const char* support : {"left", "right"})
        CHECK(staticReaction(*s->run, support, Dof::uy) == doctest::Approx(5000).epsilon(1e-12));
    CHECK(staticReaction(*aliased.run, "right", Dof::uy) ==
          staticReaction(*plain.run, "right", Dof::uy));
  }

  TEST_CASE("aliases that expand without end are refused at a place, quickly") {
    // Nine levels of ten aliases each: 10^9 values once expanded.
    std::string bomb = "l0: &l0 [a, a, a, a, a, a, a, a, a, a]\n";
    for (int i = 1; i <= 9; ++i) {
      const std::string previous = std::to_string(i - 1), index = std::to_string(i);
      const std::string prev = "*l" + previous;
      bomb += "l" + index + ": &l" + index + " [";
      for (int k = 0; k < 10; ++k) bomb += prev + (k < 9 ? ", " : "]\n");
    }
    try {
      parseDeckText(bomb + "title: x\n", "bomb.yaml");
      FAIL("an alias bomb was accepted");
    } catch (const DeckError& e) {
      CHECK(e.message().find("aliases (*name) are expanded") != std::string::npos);
      CHECK(e.place().line >= 1);
      CHECK(e.place().line <= 10);
    }
    // A list holding an alias of itself.
    try {
      parseDeckText("title: &x [*x]\n", "self.yaml");
      FAIL("a self-containing alias was accepted");
    } catch (const DeckError& e) {
      CHECK(e.message().find("nested deeper than") != std::string::npos);
      CHECK(e.place().line == 1);
    }
  }

  TEST_CASE("a key twice, or a key that is not a word, is refused at that key") {
    const DeckError twice = readingError(
        "title: first\nmodel: {dimension: planar}\ntitle: second\n", "twice.yaml");
    CHECK(twice.message() == "duplicate key 'title' (it appears earlier in the same map)");
    CHECK(twice.place().line == 3);
    CHECK(twice.place().field == "title");

    std::string nested = treeTestBeam("[uy]", "[uy]");
    nested.replace(nested.find("elements: 4"), 11, "elements: 4, length: 3.0");
    const DeckError inner = readingError(nested, "inner.yaml");
    CHECK(inner.message() == "duplicate key 'length' (it appears earlier in the same map)");
    CHECK(inner.place().line == 5);
    CHECK(inner.place().field == "segments[0].length");

    const DeckError notWord = readingError("title: x\n? [a, b]\n: 1\n", "key.yaml");
    CHECK(notWord.message() == "a key must be a plain word");
    CHECK(notWord.place().line == 2);
  }

  TEST_CASE("the tree keeps yaml-cpp's kinds, texts and places") {
    const DeckSource source =
        parseDeckText("title: beam\nlist: [1, ~, 'null']\nempty:\n", "kinds.yaml");
    const DeckNode& root = source.tree->root();
    REQUIRE(root.kind == DeckNode::Kind::map);
    CHECK(root.plainUniqueKeys);
    REQUIRE(root.entries.size() == 3);
    const DeckNode& list = *root.entries[1].second;
    REQUIRE(list.kind == DeckNode::Kind::list);
    REQUIRE(list.items.size() == 3);
    CHECK(list.items[0]->kind == DeckNode::Kind::scalar);
    CHECK(list.items[0]->text == "1");
    CHECK(list.items[0]->line == 2);
    CHECK(list.items[0]->column == 8);
    CHECK(list.items[1]->kind == DeckNode::Kind::null);    // a plain ~ is null
    CHECK(list.items[2]->kind == DeckNode::Kind::scalar);  // a quoted 'null' is text
    CHECK(list.items[2]->text == "null");
    CHECK(root.entries[2].second->kind == DeckNode::Kind::null);  // a key with no value
    CHECK(source.tree->file() == "kinds.yaml");
  }
}

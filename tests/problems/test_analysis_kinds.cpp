// The table of analysis kinds (problems/deck/AnalysisKinds.hpp) against the format's own list
// of analysis types in FORMAT.md, and the reader's use of it.
#include <doctest/doctest.h>

#include <algorithm>
#include <fstream>
#include <regex>
#include <set>
#include <sstream>
#include <string>
#include <vector>

#include "problems/deck/AnalysisKinds.hpp"
#include "problems/deck/DeckReader.hpp"
#include "problems/deck/parse/DeckSource.hpp"
#include "tests/problems/DeckTestSupport.hpp"

namespace beamrotor {

namespace {

/// The backquoted words of FORMAT.md's sentence "An analysis' `type:` is one of ...;".
std::vector<std::string> formatTypeList() {
  std::ifstream in(test::problemsDir() / "deck" / "FORMAT.md");
  std::stringstream text;
  text << in.rdbuf();
  const std::string doc = text.str();
  const std::string lead = "An analysis' `type:` is one of ";
  const std::size_t from = doc.find(lead);
  REQUIRE(from != std::string::npos);
  const std::size_t to = doc.find(';', from);
  REQUIRE(to != std::string::npos);
  const std::string list = doc.substr(from + lead.size(), to - from - lead.size());
  const std::regex word("`([^`]+)`");
  std::vector<std::string> names;
  for (std::sregex_iterator m(list.begin(), list.end(), word), end; m != end; ++m)
    names.push_back((*m)[1]);
  return names;
}

const char* const kModelDeck = R"(
materials: [{name: steel, E: 210e9, nu: 0.3, rho: 7850}]
sections: [{name: rod, shape: circle, D: 0.02}]
segments: [{length: 1, section: rod, elements: 4}]
supports: [{name: root, at: start, fix: clamped}]
)";

}  // namespace

TEST_SUITE("analysis kinds") {
  TEST_CASE("every analysis type FORMAT.md lists has exactly one row, and every row is listed") {
    const std::vector<std::string> listed = formatTypeList();
    const std::vector<std::string> rows = analysisTypeNames();
    CHECK(listed.size() == 18);
    for (const std::string& name : listed) {
      CAPTURE(name);
      CHECK(std::count(rows.begin(), rows.end(), name) == 1);
    }
    for (const std::string& name : rows) {
      CAPTURE(name);
      CHECK(std::count(listed.begin(), listed.end(), name) == 1);
    }
    CHECK(rows.size() == std::variant_size_v<AnalysisSpec>);
  }

  TEST_CASE("each row's deck name leads back to that row") {
    const std::vector<std::string> rows = analysisTypeNames();
    for (std::size_t i = 0; i < rows.size(); ++i) {
      CAPTURE(rows[i]);
      const std::optional<AnalysisSpec> spec = analysisSpecNamed(rows[i]);
      REQUIRE(spec.has_value());
      CHECK(spec->index() == i);
      CHECK(analysisTypeName(*spec) == rows[i]);
    }
    CHECK_FALSE(analysisSpecNamed("Static").has_value());
    CHECK_FALSE(analysisSpecNamed("").has_value());
  }

  TEST_CASE("an unknown type is refused with the list of known ones") {
    const DeckError e =
        test::readingError(std::string(kModelDeck) + "analyses: [{type: stattic}]\n", "kinds.yaml");
    const std::string message = e.message();
    CAPTURE(message);
    CHECK(message.find("unknown value 'stattic'") != std::string::npos);
    CHECK(message.find("did you mean 'static'") != std::string::npos);
    for (const std::string& name : formatTypeList()) {
      CAPTURE(name);
      CHECK(message.find(name) != std::string::npos);
    }
    CHECK(e.place().line == 6);
  }

  TEST_CASE("the check quantities each row answers") {
    // Every quantity the grammar knows is answered by the row the format names for it.
    const std::vector<std::pair<std::string, std::string>> defaults{
        {"reaction left uy", "static"},
        {"displacement end uy", "static"},
        {"stress max", "static"},
        {"shear max", "static"},
        {"moment max", "static"},
        {"displacement max", "static"},
        {"member beam Mz maxabs", "static"},
        {"member beam deflection max", "static"},
        {"frequency 2", "modal"},
        {"buckling_factor 1", "buckling"},
        {"log_decrement 1", "rotor"},
        {"critical_speed 1", "campbell"},
        {"unbalance_amplitude disk at 3000", "unbalance"},
        {"rigid_body f1", "rigid-body"},
        {"crank v_max", "crank-slider"},
        {"history tip max", "transient"},
        {"history tip min", "transient"},
        {"history tip maxabs", "transient"},
        {"history tip at 0.1", "transient"},
        {"resultant Mz at mid", "static"},
        {"moving max reaction left uy", "moving-load"},
        {"moving min resultant Vy at mid", "moving-load"},
        {"spectrum displacement tip uy", "response-spectrum"},
        {"effective_mass 2 x", "response-spectrum"},
        {"base_motion transmissibility tip max", "base-motion"}};
    for (const auto& [text, type] : defaults) {
      CAPTURE(text);
      const Quantity q = parseQuantity(text);
      CHECK(defaultAnalysisType(q) == type);
      CHECK(answers(*analysisSpecNamed(type), q));
    }
    // A rotor analysis also gives frequencies (its damped ones), a torsion analysis those of
    // the twist and a response-spectrum analysis those of the modes it combines; no other row
    // does.
    const Quantity frequency = parseQuantity("frequency 1");
    for (const std::string& type : analysisTypeNames()) {
      CAPTURE(type);
      CHECK(answers(*analysisSpecNamed(type), frequency) ==
            (type == "modal" || type == "rotor" || type == "torsion" ||
             type == "response-spectrum"));
    }
    CHECK_FALSE(answers(*analysisSpecNamed("frequency-response"), frequency));
  }

  TEST_CASE("a check is refused by the rows that do not answer it") {
    const std::string statics =
        std::string(kModelDeck) + "analyses: [{type: static, name: bending}]\n";
    const DeckError none = test::readingError(
        statics + "checks: [{name: f1, quantity: frequency 1, reference: 1, tolerance: 0.1}]\n",
        "kinds.yaml");
    CHECK(none.message() == "'frequency 1' needs a modal analysis; add {type: modal} to analyses");
    const DeckError named = test::readingError(
        statics +
            "checks: [{name: f1, quantity: frequency 1, reference: 1, tolerance: 0.1, "
            "analysis: bending}]\n",
        "kinds.yaml");
    CHECK(named.message() == "'frequency 1' needs a modal analysis; 'bending' is static");
  }

  TEST_CASE("the rows that need mass refuse a deck without inertia; the others read it") {
    std::string massless(kModelDeck);
    massless.replace(massless.find("rho: 7850"), 9, "rho: 0");
    const auto withAnalysis = [&](const std::string& entry) {
      return massless + "analyses: [" + entry + "]\n";
    };
    const DeckError modal = test::readingError(withAnalysis("{type: modal}"), "kinds.yaml");
    CHECK(modal.message() ==
          "a modal analysis needs mass: give the materials a density rho or add masses");
    CHECK(modal.place().line == 6);
    for (const std::string type : {"static", "buckling"}) {
      CAPTURE(type);
      const Deck deck =
          readDeck(parseDeckText(withAnalysis("{type: " + type + "}"), "kinds.yaml"), {});
      REQUIRE(deck.analyses.size() == 1);
      CHECK(deck.analyses[0].type() == type);
    }
  }
}

}  // namespace beamrotor

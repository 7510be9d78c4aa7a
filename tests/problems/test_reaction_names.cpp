// Reactions carry one set of names everywhere a reader meets them: the summary printed by
// `solve`, results.json and a sweep's table (fx fy fz mx my mz), with the cantilever's
// closed-form values P and P L.
#include <doctest/doctest.h>

#include <map>
#include <set>
#include <sstream>
#include <string>

#include "tests/Helpers.hpp"
#include "tests/problems/DeckTestSupport.hpp"

using namespace beamrotor::test;

namespace {

/// The summary's reaction line of `support` ("    root   fy 1000 N   mz 1200 N m") as
/// name -> value.
std::map<std::string, double> summaryReactions(const std::string& summary,
                                               const std::string& support) {
  std::istringstream lines(summary);
  std::string line;
  bool inReactions = false;
  while (std::getline(lines, line)) {
    if (line.find("reactions (") != std::string::npos) inReactions = true;
    std::istringstream words(line);
    std::string first;
    words >> first;
    if (!inReactions || first != support) continue;
    // Every reaction name is followed by its value; units and padding are skipped.
    std::map<std::string, double> out;
    const std::set<std::string> names{"fx", "fy", "fz", "mx", "my", "mz", "ux", "uy",
                                      "uz", "rx", "ry", "rz"};
    std::string word;
    while (words >> word)
      if (names.count(word)) words >> out[word];
    return out;
  }
  return {};
}

}  // namespace

TEST_SUITE("reaction names") {
  TEST_CASE("summary and results.json name the cantilever's reactions alike, with P and P L") {
    const SolvedDeck solved = solveShippedDeckToScratch("cantilever.yaml", "reaction-names");
    const auto fromSummary = summaryReactions(solved.process.out, "root");
    const nlohmann::json fromJson = solved.json("results.json")["analyses"][0]["reactions"]["root"];
    std::set<std::string> summaryNames, jsonNames;
    for (const auto& [name, value] : fromSummary) summaryNames.insert(name);
    for (const auto& [name, value] : fromJson.items()) jsonNames.insert(name);
    CHECK(summaryNames == std::set<std::string>{"fx", "fy", "mz"});
    CHECK(summaryNames == jsonNames);
    // Closed form: the clamp holds the tip force P = 1000 N up and the moment P L = 1200 N m.
    // results.json has every digit: round-off only (the deck observes ~5e-12 on its checks;
    // 1e-10 leaves a margin); the summary prints 6 significant digits (half a unit: 5e-6).
    const double P = 1000, L = 1.2;
    CHECK(relError(fromJson["fy"].get<double>(), P) < 1e-10);
    CHECK(relError(fromJson["mz"].get<double>(), P * L) < 1e-10);
    CHECK(relError(fromSummary.at("fy"), P) < 5e-6);
    CHECK(relError(fromSummary.at("mz"), P * L) < 5e-6);
    std::filesystem::remove_all(solved.dir.parent_path());
  }

  TEST_CASE("a sweep's summary table heads its reaction columns like sweep.csv") {
    const SolvedDeck solved = solveShippedDeckToScratch("pump_rod_hinged.yaml", "reaction-sweep");
    const std::string csv = solved.text("sweep.csv");
    for (const std::string name : {"left fy", "middle fy", "right fy", "right mz"}) {
      CAPTURE(name);
      CHECK(solved.process.out.find(name) != std::string::npos);
      const std::string support = name.substr(0, name.find(' ')),
                        component = name.substr(name.find(' ') + 1);
      // The column's name, the whole name (the names line holds no units).
      const std::string header = csv.substr(0, csv.find('\n')) + ",";
      CHECK(header.find("." + support + "." + component + ",") != std::string::npos);
    }
    // The table's head line (the checks below name their deck quantity, `reaction left uy`).
    const std::string& out = solved.process.out;
    const std::size_t head = out.find("  eta ");
    REQUIRE(head != std::string::npos);
    const std::string headLine = out.substr(head, out.find('\n', head) - head);
    CHECK(headLine.find("left fy") != std::string::npos);
    CHECK(headLine.find(" uy") == std::string::npos);
    std::filesystem::remove_all(solved.dir.parent_path());
  }
}

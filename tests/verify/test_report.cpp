// The verification report: deck checks collected through the library, and one self-contained
// HTML page with the failure-case charts inlined.
#include <doctest/doctest.h>

#include <cmath>
#include <fstream>
#include <numbers>
#include <sstream>

#include "problems/output/Gnuplot.hpp"
#include "problems/verify/HtmlPage.hpp"
#include "problems/verify/Report.hpp"
#include "tests/problems/DeckTestSupport.hpp"

using namespace beamrotor;
using namespace beamrotor::verify;

namespace {

int occurrences(const std::string& text, const std::string& what) {
  int n = 0;
  for (auto at = text.find(what); at != std::string::npos; at = text.find(what, at + 1)) ++n;
  return n;
}

}  // namespace

TEST_SUITE("verification report") {
  TEST_CASE("the deck checks are the deck's closed forms, computed through the library") {
    const auto rows = runDeckChecks({test::problemsDir() / "cantilever.yaml"});
    REQUIRE(rows.size() == 1);
    CHECK(rows[0].error.empty());
    // problems/cantilever.yaml: P = 1000 N, L = 1.2 m, D = 0.05 m, E = 210 GPa; the tip
    // deflection -P L^3 / (3 E I) is exact for Hermite elements (round-off only).
    const double I = std::numbers::pi * std::pow(0.05, 4) / 64;
    const double tip = -1000 * std::pow(1.2, 3) / (3 * 210e9 * I);
    bool found = false;
    for (const auto& [label, c] : rows[0].checks)
      if (c.name == "tip deflection") {
        found = true;
        CHECK(std::abs(c.computed - tip) / std::abs(tip) < 1e-9);
        CHECK(c.pass());
      }
    CHECK(found);
  }

  TEST_CASE("a deck that cannot be read is a row with its one-line error, not an abort") {
    const auto dir = test::scratchDir("report_bad_deck");
    std::ofstream(dir / "broken.yaml") << "title: broken\nsegments: 3\n";
    const auto rows = runDeckChecks(decksIn(dir));
    REQUIRE(rows.size() == 1);
    CHECK(rows[0].error.find("broken.yaml:") != std::string::npos);  // file:line:col: ...
    CHECK(rows[0].error.find('\n') == std::string::npos);
    std::filesystem::remove_all(dir);
  }

  TEST_CASE("the page is self-contained: charts inlined, nothing fetched") {
    const auto dir = test::scratchDir("report_page");
    std::filesystem::create_directories(dir / "decks");
    std::filesystem::copy_file(test::problemsDir() / "cantilever.yaml",
                               dir / "decks" / "cantilever.yaml");
    ReportOptions options;
    options.outDir = dir / "out";
    options.problemsDir = dir / "decks";
    options.failures.largestMesh = 1000;
    // A chart as `beamrotor converge` would leave it (the hook for the convergence section).
    std::filesystem::create_directories(options.outDir / "convergence" / "cantilever");
    std::ofstream(options.outDir / "convergence" / "cantilever" / "error_vs_dofs.svg")
        << "<?xml version=\"1.0\"?>\n<svg id=\"converge-marker\"></svg>\n";
    std::ostringstream log;
    const ReportSummary s = writeReport(options, log);
    CHECK(s.checks == 7);  // the cantilever deck's seven checks
    CHECK(s.failedChecks == 0);
    std::ifstream in(s.page);
    std::stringstream text;
    text << in.rdbuf();
    const std::string html = text.str();
    CHECK(html.find("7 of 7 checks pass") != std::string::npos);
    CHECK(occurrences(html, "<figcaption>") == 8);  // the convergence chart, 7 failure cases
    CHECK(html.find("Convergence: cantilever/error_vs_dofs") != std::string::npos);
    CHECK(html.find("<svg id=\"converge-marker\">") != std::string::npos);
    if (findGnuplot()) CHECK(occurrences(html, "<svg") == 8);
    CHECK(html.find("<?xml") == std::string::npos);
    // Text is escaped: the free-free caption quotes the solver's message.
    CHECK(html.find("error (&quot;") != std::string::npos);
    for (const char* external : {"src=", "<link", "<script", "href=\"http", "url("})
      CHECK(html.find(external) == std::string::npos);
    std::filesystem::remove_all(dir);
  }

}

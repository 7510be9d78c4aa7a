// The verification report: deck checks collected through the library, and one self-contained
// HTML page with the failure-case charts inlined.
#include <doctest/doctest.h>

#include <cmath>
#include <fstream>
#include <numbers>
#include <sstream>

#include "problems/output/files/Gnuplot.hpp"
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

/// A cantilever of length L under P at its tip (E I = 1e4 N m^2), written to dir/decks/name
/// with `extra` (parameters, checks, a sweep) after it.
void writeReportCantilever(const std::filesystem::path& dir, const std::string& name,
                           const std::string& extra) {
  std::filesystem::create_directories(dir / "decks");
  std::ofstream(dir / "decks" / name)
      << "materials: [{name: m, E: 1e11, nu: 0.3}]\n"
         "sections: [{name: s, shape: general, A: 1e-3, I: 1e-7, depth: 0.01}]\n"
         "segments: [{length: L, section: s, elements: 4}]\n"
         "points: [{name: root, at: 0}, {name: tip, at: L}]\n"
         "supports: [{name: root, at: root, fix: clamped}]\n"
         "loads: [{type: point, at: tip, fy: -P}]\n"
      << extra;
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

  TEST_CASE("checks that did not apply are listed with their condition and counted") {
    // A cantilever (P = 1000 N, L = 1, E I = 1e4 N m^2 through a general section) with three
    // checks: the tip deflection P L^3 / (3 E I) = 1/30 m (exact for Hermite elements), one
    // whose when: is false at these parameters, and a sweep of P over two values in which the
    // third applies only at P = 2000. The page must show those left out as rows with their
    // condition, and the headline must count them: 3 pass (tip at both values, heavy at
    // P = 2000), 0 fail, 3 did not apply (light at both values, heavy at P = 1000).
    const auto dir = test::scratchDir("report_not_applied");
    writeReportCantilever(
        dir, "cantilever_when.yaml",
        "title: cantilever with conditional checks\n"
        "parameters: {P: 1000, L: 1}\n"
        "checks:\n"
        "  - {name: tip, quantity: displacement tip uy, reference: -P*L^3/(3*1e4),"
        " tolerance: 1e-9}\n"
        "  - {name: light, quantity: reaction root uy, reference: P, tolerance: 1e-9,"
        " when: P < 500}\n"
        "  - {name: heavy, quantity: reaction root uy, reference: P, tolerance: 1e-9,"
        " when: P > 1500}\n"
        "sweep: {parameter: P, values: [1000, 2000]}\n");
    const auto rows = runDeckChecks(decksIn(dir / "decks"));
    REQUIRE(rows.size() == 1);
    REQUIRE(rows[0].error.empty());
    CHECK(rows[0].checks.size() == 3);        // tip twice, heavy at P = 2000
    REQUIRE(rows[0].notApplied.size() == 3);  // light twice, heavy at P = 1000
    CHECK(rows[0].notApplied[0].name == "light");
    CHECK(rows[0].notApplied[0].label == "P = 1000");
    CHECK(rows[0].notApplied[0].why == "when: P < 500 is false here");
    for (const auto& [label, c] : rows[0].checks) {
      CHECK(c.pass());
      if (c.name == "tip") {
        const double P = label == "P = 1000" ? 1000 : 2000;
        CHECK(std::abs(c.computed + P / 3e4) <= 1e-9 * P / 3e4);
      }
    }
    ReportContent content;
    content.decks = rows;
    const std::string html = reportHtml(content);
    CHECK(html.find("3 of 3 checks pass, 0 fail, 3 did not apply") != std::string::npos);
    CHECK(occurrences(html, "<td>did not apply</td>") == 3);
    CHECK(html.find("when: P &gt; 1500 is false here") != std::string::npos);
    std::filesystem::remove_all(dir);
  }

  TEST_CASE("a check's paper figure and reason reach the page and results.json") {
    // The tip deflection of the same cantilever, 1/30 m, with a "paper" printing 0.0335 (a
    // rounding): the page shows the printed figure, its difference 0.5 % and the reason.
    const auto dir = test::scratchDir("report_paper_note");
    writeReportCantilever(dir, "cantilever_paper.yaml",
                          "parameters: {P: 1000, L: 1}\n"
                          "checks:\n"
                          "  - {name: tip, quantity: displacement tip uy, reference: -1/30, "
                          "tolerance: 1e-9,\n"
                          "     paper: -0.0335, reason: rounded up in print}\n");
    const auto rows = runDeckChecks(decksIn(dir / "decks"));
    REQUIRE(rows.size() == 1);
    REQUIRE(rows[0].checks.size() == 1);
    const Check& c = rows[0].checks[0].second;
    REQUIRE(c.paper);
    CHECK(*c.paper == -0.0335);
    CHECK(c.reason == "rounded up in print");
    CHECK(c.pass());  // the reference, not the paper's figure, decides
    ReportContent content;
    content.decks = rows;
    const std::string html = reportHtml(content);
    // |1/30 - 0.0335| / 0.0335 = 0.004975
    CHECK(html.find("paper prints -0.0335 (differs from the computed value by 0.005 relative): "
                    "rounded up in print") != std::string::npos);
    std::filesystem::remove_all(dir);
  }
}

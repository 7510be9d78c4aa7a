// `beamrotor report --converge` (what `make report` runs): every deck's convergence study first,
// a deck with nothing to converge skipped and named on the page rather than stopping the report.
#include <doctest/doctest.h>

#include <filesystem>
#include <fstream>
#include <sstream>

#include "problems/cli/ReportCommand.hpp"
#include "tests/problems/DeckTestSupport.hpp"

namespace beamrotor {

TEST_SUITE("report cli") {
  TEST_CASE("report --converge studies each deck and skips, by name, one with nothing to refine") {
    namespace fs = std::filesystem;
    const fs::path dir = test::scratchDir("report_converge");
    fs::create_directories(dir / "decks");
    // A rigid body given by its own data (closed forms, no mesh) beside a meshed cantilever.
    for (const char* deck : {"forme_shaft_two_dof.yaml", "cantilever.yaml"})
      fs::copy_file(test::problemsDir() / deck, dir / "decks" / deck);
    cli::ReportRequest request;
    request.report.outDir = dir / "out";
    request.report.problemsDir = dir / "decks";
    request.report.failures.largestMesh = 1000;
    request.converge = true;
    std::ostringstream out, err;
    REQUIRE_MESSAGE(cli::reportCommand(request, out, err) == 0, err.str());
    CHECK(out.str().find("1 deck(s) with nothing to converge") != std::string::npos);
    CHECK(err.str().find("forme_shaft_two_dof.yaml: skipped, nothing to converge") !=
          std::string::npos);
    // The cantilever's study ran into convergence/cantilever/, the mechanism's did not.
    CHECK(fs::exists(dir / "out" / "convergence" / "cantilever" / "convergence.json"));
    CHECK_FALSE(fs::exists(dir / "out" / "convergence" / "forme_shaft_two_dof"));
    std::ifstream in(dir / "out" / "index.html");
    std::stringstream page;
    page << in.rdbuf();
    const std::string html = page.str();
    CHECK(html.find("Decks without a convergence study") != std::string::npos);
    CHECK(html.find("<code>forme_shaft_two_dof.yaml</code>: nothing to converge") !=
          std::string::npos);
    CHECK(html.find("Convergence: cantilever/convergence_dofs") != std::string::npos);
    fs::remove_all(dir);
  }
}

}  // namespace beamrotor

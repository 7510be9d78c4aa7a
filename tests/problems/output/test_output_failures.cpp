// A results directory is complete or absent: non-finite results are refused before writing,
// a failed write leaves an earlier directory as it was, a directory that is not ours is never
// replaced, and a missing gnuplot costs the charts only.
#include <doctest/doctest.h>

#include <cmath>
#include <cstdlib>
#include <limits>

#include "problems/output/files/AtomicDirectory.hpp"
#include "problems/output/Output.hpp"
#include "tests/problems/output/OutputFixtures.hpp"

using namespace beamrotor;
using namespace beamrotor::test;
namespace fs = std::filesystem;

namespace {

/// The error message of writeRunOutputs, or "" when it did not throw std::runtime_error.
std::string writeError(const RunResult& run, const fs::path& dir) {
  try {
    writeRunOutputs(run, dir);
  } catch (const std::runtime_error& e) {
    return e.what();
  }
  return "";
}

}  // namespace

TEST_SUITE("output") {
  TEST_CASE("a non-finite number is refused, naming it, and leaves no directory behind") {
    const Cantilever c;
    RunResult run = cantileverRun(c, 2);
    ScratchDir scratch;
    const fs::path out = scratch / "out";
    const double nan = std::numeric_limits<double>::quiet_NaN();

    SUBCASE("NaN in a displacement") {
      auto& statics = *staticsOf(run.analyses[0]);
      statics.displacement(3, dofIndex(Dof::uy)) = nan;
      const std::string error = writeError(run, out);
      CHECK(error.find("displacement") != std::string::npos);
      CHECK(error.find("node 3") != std::string::npos);
      CHECK(error.find("uy") != std::string::npos);
    }
    SUBCASE("infinite frequency") {
      resultOf<ModalResult>(run.analyses[1])->modes[1].frequencyHz =
          std::numeric_limits<double>::infinity();
      const std::string error = writeError(run, out);
      CHECK(error.find("mode 2 frequency") != std::string::npos);
    }
    SUBCASE("NaN in a check") {
      run.checks[0].computed = nan;
      CHECK(writeError(run, out).find("check 'tip deflection'") != std::string::npos);
    }
    // Nothing was created: neither the directory nor a temporary sibling.
    CHECK_FALSE(fs::exists(out));
    CHECK(scratch.entries().empty());
  }

  TEST_CASE("a failed write keeps the earlier results; a good one replaces them entirely") {
    const Cantilever c;
    ScratchDir scratch;
    const fs::path out = scratch / "out";
    writeRunOutputs(cantileverRun(c, 2), out);
    REQUIRE(fs::exists(out / "modes.pvd"));
    const std::string before = readText(out / "results.json");

    RunResult broken = cantileverRun(c);
    staticsOf(broken.analyses[0])->reactions[0].value = std::numeric_limits<double>::quiet_NaN();
    CHECK(writeError(broken, out).find("reaction of support 'root'") != std::string::npos);
    CHECK(readText(out / "results.json") == before);
    CHECK(scratch.entries() == std::vector<std::string>{"out"});

    Cantilever heavier = c;
    heavier.P = 2 * c.P;
    writeRunOutputs(cantileverRun(heavier), out);  // statics only this time
    const auto doc = readJson(out / "results.json");
    CHECK(doc["analyses"][0]["reactions"]["root"]["fy"].get<double>() ==
          doctest::Approx(heavier.P).epsilon(1e-10));
    CHECK_FALSE(fs::exists(out / "modes.pvd"));  // no stale files from the earlier run
    CHECK(scratch.entries() == std::vector<std::string>{"out"});
  }

  TEST_CASE("a directory that is not beamrotor output is never replaced") {
    ScratchDir scratch;
    const fs::path mine = scratch / "thesis";
    fs::create_directories(mine);
    std::ofstream(mine / "chapter1.tex") << "precious";
    CHECK(writeError(cantileverRun(Cantilever{}), mine).find("refusing to replace") !=
          std::string::npos);
    CHECK(readText(mine / "chapter1.tex") == "precious");
    CHECK(scratch.entries() == std::vector<std::string>{"thesis"});
  }

  TEST_CASE("analyses whose names map to the same files are refused") {
    RunResult run = cantileverRun(Cantilever{});
    run.analyses.push_back(run.analyses[0]);
    run.analyses[0].name = "tip load";
    run.analyses[1].name = "tip/load";
    ScratchDir scratch;
    CHECK_THROWS_AS(writeRunOutputs(run, scratch / "out"), std::invalid_argument);
    CHECK_FALSE(fs::exists(scratch / "out"));
  }

  TEST_CASE("without gnuplot the run is written, charts skipped") {
    const ScopedEnvironment noGnuplot("BEAMROTOR_GNUPLOT", "/nonexistent/gnuplot");
    ScratchDir scratch;
    writeRunOutputs(cantileverRun(Cantilever{}, 2), scratch / "out");
    CHECK(fs::exists(scratch / "out" / "results.json"));
    CHECK(fs::exists(scratch / "out" / "tip.vtu"));
    CHECK_FALSE(fs::exists(scratch / "out" / "tip_diagrams.svg"));
    CHECK_FALSE(fs::exists(scratch / "out" / "tip_diagrams.gp"));
  }

  TEST_CASE("writeDirectoryAtomically: a writer failing half-way leaves nothing half-written") {
    ScratchDir scratch;
    const fs::path out = scratch / "out";
    const auto failHalfWay = [](const fs::path& dir) {
      std::ofstream(dir / "results.json") << "{}";
      throw std::runtime_error("disk full");
    };
    SUBCASE("no earlier directory") {
      CHECK_THROWS_WITH_AS(writeDirectoryAtomically(out, failHalfWay), "disk full",
                           std::runtime_error);
      CHECK(scratch.entries().empty());
    }
    SUBCASE("an earlier directory stays as it was") {
      fs::create_directories(out);
      std::ofstream(out / "results.json") << "earlier";
      CHECK_THROWS_AS(writeDirectoryAtomically(out, failHalfWay), std::runtime_error);
      CHECK(readText(out / "results.json") == "earlier");
      CHECK(scratch.entries() == std::vector<std::string>{"out"});
    }
  }

  TEST_CASE("writeDirectoryAtomically: trailing separator, nested parents, usual permissions") {
    ScratchDir scratch;
    const fs::path nested = scratch / "a";
    writeDirectoryAtomically(nested / "b" / "out/", [](const fs::path& dir) {
      std::ofstream(dir / "results.json") << "{}";
    });
    CHECK(fs::exists(nested / "b" / "out" / "results.json"));
    CHECK(fs::directory_iterator(nested / "b")->path().filename() == "out");  // nothing else
    // Same permissions as a directory made by mkdir here (the umask decides, not 0700).
    fs::create_directory(scratch / "reference");
    CHECK(fs::status(nested / "b" / "out").permissions() ==
          fs::status(scratch / "reference").permissions());
    // "." and ".." name no directory of their own; "scratch/.." is the scratch's parent,
    // which is not ours and so is refused too.
    const auto nothing = [](const fs::path&) {};
    CHECK_THROWS_AS(writeDirectoryAtomically(".", nothing), std::invalid_argument);
    CHECK_THROWS_AS(writeDirectoryAtomically("..", nothing), std::invalid_argument);
    CHECK_THROWS_WITH_AS(writeDirectoryAtomically(nested / "..", nothing),
                         doctest::Contains("refusing to replace"), std::runtime_error);
  }
}

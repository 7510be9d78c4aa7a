// A design study asked to stop, and continued (problems/study/DesignStudyRun.hpp,
// StudyResume.hpp), in this process: the signal is raised from the progress callback after a
// given row, so the moment is exact. The table kept, the summary marked partial naming the
// missing points, --resume writing the uninterrupted table byte for byte, resumption refused
// for another study; and the pieces: point ranges, a table row read back, the Wilson bounds at
// the ends, failures with their parameters, a study with no successful point.
#include <doctest/doctest.h>
#include <signal.h>

#include <cmath>
#include <fstream>
#include <limits>
#include <set>
#include <string>
#include <vector>

#include "problems/output/files/Interruption.hpp"
#include "problems/study/DesignStudyRun.hpp"
#include "problems/study/PointRanges.hpp"
#include "problems/study/StudyResume.hpp"
#include "problems/study/StudyStatistics.hpp"
#include "problems/study/StudyTable.hpp"
#include "tests/problems/DeckTestSupport.hpp"

using namespace beamrotor;
using namespace beamrotor::test;
namespace fs = std::filesystem;

namespace {

/// The pump rod's stroke-and-wear grid, 21 x 11 = 231 points.
DesignStudyRequest strokeAndWear(const fs::path& out) {
  DesignStudyRequest r;
  r.deckPath = (problemsDir() / "pump_rod.yaml").string();
  r.outDir = out.string();
  r.study.sweeps = {"eta=0:0.4:20", "w0=0.5e-3:1.5e-3:10"};
  return r;
}

/// The study run until `signal` is raised after row `after` (0: never), the signal then
/// forgotten (it would end this process).
DesignStudyOutcome runUntilSignal(const DesignStudyRequest& r, long long after, int signal) {
  DesignStudyOutcome o = runDesignStudy(r, [&](long long done, long long) {
    if (done == after) ::raise(signal);
  });
  clearInterruption();
  return o;
}

/// The point numbers of a study.csv's rows.
std::vector<long long> tablePoints(const fs::path& csv) {
  std::vector<long long> points;
  const auto rows = csvCells(csv);
  for (std::size_t i = 1; i < rows.size(); ++i) points.push_back(std::stoll(rows[i][0]));
  return points;
}

std::string resumeError(const DesignStudyRequest& r) {
  try {
    runDesignStudy(r);
  } catch (const DeckError& e) {
    return e.what();
  }
  return "no error";
}

}  // namespace

TEST_SUITE("study stop and resume") {
  TEST_CASE("point ranges: runs of consecutive points, their gaps and positions") {
    PointRanges done;
    for (long long i : {0, 1, 2, 5, 6, 9}) done.append(i);
    CHECK(done.size() == 6);
    CHECK(done.runs().size() == 3);
    CHECK(done.text() == "0-2, 5-6, 9");
    const PointRanges missing = done.complement(12);
    CHECK(missing.text() == "3-4, 7-8, 10-11");
    CHECK(missing.size() == 6);
    // Positions run through the points held, in order.
    const std::vector<long long> expected{3, 4, 7, 8, 10, 11};
    for (long long p = 0; p < missing.size(); ++p) CHECK(missing.at(p) == expected[p]);
    CHECK(missing.lastInRun(2) == 8);
    CHECK(PointRanges::all(4).complement(4).empty());
    CHECK(PointRanges().complement(3).text() == "0-2");
    CHECK(done.text(2) == "0-2, 5-6, ... and 1 more");
  }

  TEST_CASE("a table row reads back bit for bit, and what is no row is refused") {
    StudyRow shape;
    shape.parameters.assign(2, 0);
    shape.outputs.assign(2, 0);
    shape.checks.assign(1, 0);
    shape.passed.assign(1, -1);
    StudyRow row = shape;
    row.index = 41;
    row.parameters = {0.1, 1.0 / 3.0};
    row.outputs = {-2.718281828459045e-300, std::numeric_limits<double>::quiet_NaN()};
    row.checks = {std::nextafter(1.0, 2.0)};
    row.passed = {0};
    row.status = "failed, \"really\" so";
    std::string line = studyCsvRow(row);
    line.pop_back();
    const auto back = parseStudyCsvRow(line, shape);
    REQUIRE(back);
    CHECK(back->index == 41);
    CHECK(back->parameters == row.parameters);
    CHECK(back->outputs[0] == row.outputs[0]);
    CHECK(std::isnan(back->outputs[1]));
    CHECK(back->checks[0] == row.checks[0]);
    CHECK(back->passed[0] == 0);
    CHECK(back->status == row.status);
    CHECK(studyCsvRow(*back) == line + "\n");
    CHECK_FALSE(parseStudyCsvRow("41,0.1", shape));              // cut short
    CHECK_FALSE(parseStudyCsvRow("x,0.1,0.2,1,2,3,1,ok", shape));  // no point number
    CHECK_FALSE(parseStudyCsvRow("4,0.1,0.2,1,2,3,7,ok", shape));  // a pass that is not 0/1
  }

  TEST_CASE("the Wilson bounds at no and at every success are 0 and 1 exactly") {
    // The score formula leaves round-off there (2.168e-19 at 0 of 1000).
    CHECK(wilsonInterval(0, 1000).low == 0.0);
    CHECK(wilsonInterval(100, 100).high == 1.0);
    CHECK(wilsonInterval(10, 10).high == 1.0);
    CHECK(wilsonInterval(1, 1000).low > 0.0);
  }

  TEST_CASE("stopped after row 40: the rows done are kept, the rest named missing") {
    const fs::path scratch = scratchDir("study-stop");
    const DesignStudyOutcome o =
        runUntilSignal(strokeAndWear(scratch / "s"), 40, SIGINT);
    CHECK(o.signal == SIGINT);
    REQUIRE(o.partial());
    // Serially no point starts after the signal: exactly the 40 rows before it.
    CHECK(o.points == 40);
    CHECK(o.missing.text() == "40-230");
    CHECK(tablePoints(o.dir / "study.csv").size() == 40);
    const Json summary = Json::parse(fileContents(o.dir / "summary.json"));
    CHECK(summary["partial"] == true);
    CHECK(summary["stopped_by"] == "SIGINT");
    CHECK(summary["points"] == 40);
    CHECK(summary["missing"]["count"] == 191);
    CHECK(summary["missing"]["points"] == Json::parse("[[40, 230]]"));
    CHECK(summary["ranks"] == 1);
    CHECK_FALSE(fs::exists(o.dir / "worst"));
    CHECK(fs::exists(o.dir / kResumeFile));
    fs::remove_all(scratch);
  }

  TEST_CASE("--resume with output units (or others than the stopped run's): the same table") {
    // study.csv holds the columns' own units, which its units line names: the output units
    // change the summary and the worst point's files only, so a study stopped in one choice
    // of units and resumed in another (or in none) gives the uninterrupted table.
    const fs::path scratch = scratchDir("study-resume-units");
    DesignStudyRequest whole = strokeAndWear(scratch / "whole");
    const DesignStudyOutcome reference = runDesignStudy(whole);
    REQUIRE_FALSE(reference.partial());
    for (const char* resumedIn : {"length=mm,force=kN", ""}) {
      CAPTURE(resumedIn);
      DesignStudyRequest r = strokeAndWear(scratch / (std::string("part-") + resumedIn));
      r.units = parseOutputUnits("length=mm,stress=MPa");
      const DesignStudyOutcome part = runUntilSignal(r, 40, SIGTERM);
      REQUIRE(part.partial());
      r.units = *resumedIn ? parseOutputUnits(resumedIn) : OutputUnits();
      r.resumeDir = r.outDir;
      r.outDir.clear();
      const DesignStudyOutcome resumed = runDesignStudy(r);
      CHECK_FALSE(resumed.partial());
      CHECK(resumed.resumed == 40);
      CHECK(fileContents(resumed.dir / "study.csv") == fileContents(reference.dir / "study.csv"));
      CHECK(fileContents(resumed.dir / "summary.json") ==
            fileContents(reference.dir / "summary.json"));
      // The table reads back as written: a names line, a units line, then the rows.
      const auto rows = csvCells(resumed.dir / "study.csv");
      CHECK(rows.size() == 1 + 231);
      CHECK(fileContents(resumed.dir / "study.csv").find("\n# units: ,m,m,") !=
            std::string::npos);
    }
    fs::remove_all(scratch);
  }

  TEST_CASE("--resume of a stopped study writes the uninterrupted table byte for byte") {
    const fs::path scratch = scratchDir("study-resume");
    // 81 x 61 points: more than threads may solve ahead of the table (4096 rows, see
    // StudyExecution.cpp) past row 57, so the stop always leaves points missing.
    const auto grid = [&](const std::string& name) {
      DesignStudyRequest r = strokeAndWear(scratch / name);
      r.study.sweeps = {"eta=0:0.4:80", "w0=0.5e-3:1.5e-3:60"};
      return r;
    };
    const DesignStudyOutcome whole = runDesignStudy(grid("whole"));
    REQUIRE_FALSE(whole.partial());
    CHECK_FALSE(fs::exists(whole.dir / kResumeFile));  // a finished study has nothing to resume
    for (int threads : {1, 2}) {
      CAPTURE(threads);
      DesignStudyRequest r = grid("part" + std::to_string(threads));
      r.threads = threads;
      const DesignStudyOutcome part = runUntilSignal(r, 57, SIGTERM);
      REQUIRE(part.partial());
      // Threads hand on every row they finished: increasing point numbers, maybe with gaps.
      const std::vector<long long> kept = tablePoints(part.dir / "study.csv");
      CHECK(std::is_sorted(kept.begin(), kept.end()));
      CHECK(std::set<long long>(kept.begin(), kept.end()).size() == kept.size());
      CHECK(kept.size() + std::size_t(part.missing.size()) == 81 * 61);
      r.resumeDir = r.outDir;
      r.outDir.clear();  // the study goes where it was
      const DesignStudyOutcome resumed = runDesignStudy(r);
      CHECK_FALSE(resumed.partial());
      CHECK(resumed.resumed == (long long)kept.size());
      CHECK(resumed.dir == part.dir);
      CHECK(fileContents(resumed.dir / "study.csv") == fileContents(whole.dir / "study.csv"));
      CHECK(fileContents(resumed.dir / "summary.json") ==
            fileContents(whole.dir / "summary.json"));
      CHECK(fs::exists(resumed.dir / "worst" / "results.json"));
      CHECK_FALSE(fs::exists(resumed.dir / kResumeFile));
    }
    fs::remove_all(scratch);
  }

  TEST_CASE("--resume with --point-files: every point's directory, kept or made") {
    const fs::path scratch = scratchDir("study-resume-points");
    DesignStudyRequest r = strokeAndWear(scratch / "s");
    r.study.sweeps = {"eta=0:0.4:4"};
    r.pointFiles = true;
    // Stopped as the second row is written: its point's files are not (the study is stopping).
    const DesignStudyOutcome part = runUntilSignal(r, 2, SIGINT);
    REQUIRE(part.partial());
    CHECK(fs::exists(part.dir / "points" / "0" / "results.json"));
    CHECK_FALSE(fs::exists(part.dir / "points" / "1"));
    r.resumeDir = r.outDir;
    const DesignStudyOutcome resumed = runDesignStudy(r);
    REQUIRE_FALSE(resumed.partial());
    for (int k = 0; k < 5; ++k) {
      CAPTURE(k);
      CHECK(fs::exists(resumed.dir / "points" / std::to_string(k) / "results.json"));
    }
    fs::remove_all(scratch);
  }

  TEST_CASE("--resume refuses another study, naming what differs") {
    const fs::path scratch = scratchDir("study-resume-other");
    const DesignStudyOutcome part = runUntilSignal(strokeAndWear(scratch / "s"), 12, SIGINT);
    REQUIRE(part.partial());
    DesignStudyRequest other = strokeAndWear(scratch / "t");
    other.resumeDir = part.dir.string();
    other.study.sweeps = {"eta=0:0.3:20", "w0=0.5e-3:1.5e-3:10"};  // same size, other values
    CHECK(resumeError(other).find("--resume " + part.dir.string()) != std::string::npos);
    CHECK(resumeError(other).find("point 11 has other parameter values") != std::string::npos);
    other = strokeAndWear(scratch / "t");
    other.resumeDir = part.dir.string();
    other.sets = {"E=210e9"};
    CHECK(resumeError(other).find("had other --set overrides") != std::string::npos);
    other.sets.clear();
    other.study.sweeps = {"eta=0:0.4:10"};
    CHECK(resumeError(other).find("another number of points") != std::string::npos);
    // The deck's text changed since (a comment is enough: it could have been anything).
    const fs::path deck = scratch / "pump_rod.yaml";
    std::ofstream(deck) << fileContents(problemsDir() / "pump_rod.yaml") << "# edited\n";
    other = strokeAndWear(scratch / "t");
    other.deckPath = deck.string();
    other.resumeDir = part.dir.string();
    CHECK(resumeError(other).find("another text of the deck") != std::string::npos);
    // A finished study, or no study at all, has nothing to resume.
    const DesignStudyOutcome whole = runDesignStudy(strokeAndWear(scratch / "whole"));
    other = strokeAndWear(scratch / "t");
    other.resumeDir = whole.dir.string();
    CHECK(resumeError(other).find("no partial study there") != std::string::npos);
    CHECK_FALSE(fs::exists(scratch / "t"));
    fs::remove_all(scratch);
  }

  TEST_CASE("failures name their points' parameters") {
    const fs::path scratch = scratchDir("study-failures");
    DesignStudyRequest r = strokeAndWear(scratch / "s");
    r.study.sweeps = {"eta=0.2,2"};  // eta = 2 puts the seal beyond the rod's end
    const DesignStudyOutcome o = runDesignStudy(r);
    REQUIRE(o.summary["failures"].size() == 1);
    CHECK(o.summary["failures"][0]["point"] == 1);
    CHECK(o.summary["failures"][0]["parameters"]["eta"] == 2.0);
    fs::remove_all(scratch);
  }
}

TEST_SUITE("study command line") {
  TEST_CASE("a study with no successful point exits 1 and lists no worst/") {
    const fs::path scratch = scratchDir("study-all-failed");
    const ProcessResult p = runBeamrotor({"study", "problems/pump_rod.yaml", "--sweep",
                                          "eta=2,3", "--out", (scratch / "s").string()});
    CHECK(p.exitCode == 1);
    CHECK(p.err.find("no point succeeded (2 failed") != std::string::npos);
    CHECK(p.out.find("worst/") == std::string::npos);
    CHECK(p.out.find("point 0 (eta = 2 m) failed") != std::string::npos);  // its unit named
    CHECK_FALSE(fs::exists(scratch / "s" / "worst"));
    CHECK(fs::exists(scratch / "s" / "study.csv"));  // the rows say why, still
    fs::remove_all(scratch);
  }
}

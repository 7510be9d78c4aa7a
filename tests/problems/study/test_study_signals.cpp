// `beamrotor study` as a process, signalled while it solves: SIGINT and SIGTERM end it by the
// signal with the rows it had, a summary marked partial and the way to continue; kill -9
// leaves the rows written so far in its temporary directory, which the next study into the
// same directory keeps and names, and which --resume continues to the uninterrupted table.
// Each signal is sent once the table has rows; the waits are generous and nothing here
// asserts a speed (the stop's latency is shown as a MESSAGE).
#include <doctest/doctest.h>
#include <signal.h>
#include <sys/wait.h>

#include <chrono>
#include <fstream>
#include <nlohmann/json.hpp>
#include <thread>

#include "tests/problems/DeckTestSupport.hpp"

using namespace beamrotor;
using namespace beamrotor::test;
namespace fs = std::filesystem;

namespace {

/// The pump rod over a stroke-and-wear grid of `etaSteps + 1` x 201 points.
std::vector<std::string> studyArguments(int etaSteps, const std::string& out) {
  return {"study",   (problemsDir() / "pump_rod.yaml").string(),
          "--sweep", "eta=0:0.4:" + std::to_string(etaSteps),
          "--sweep", "w0=0.5e-3:1.5e-3:200",
          "--out",   out};
}

/// The temporary directory `root/out.tmp-*` of a study writing root/out, or empty.
fs::path temporaryOf(const fs::path& root) {
  for (const auto& entry : fs::directory_iterator(root))
    if (entry.path().filename().string().rfind("out.tmp-", 0) == 0) return entry.path();
  return {};
}

/// The lines of a table other than its units line (a comment): the names and the rows.
long long lineCount(const fs::path& file) {
  std::ifstream in(file);
  long long n = 0;
  for (std::string line; std::getline(in, line);) n += line.rfind('#', 0) != 0;
  return n;
}

/// Waits (at most 60 s) until the study writing root/out has `rows` rows in its table.
void awaitRows(const fs::path& root, long long rows) {
  const auto until = std::chrono::steady_clock::now() + std::chrono::seconds(60);
  while (std::chrono::steady_clock::now() < until) {
    const fs::path temporary = temporaryOf(root);
    if (!temporary.empty() && lineCount(temporary / "study.csv") > rows) return;
    std::this_thread::sleep_for(std::chrono::milliseconds(1));
  }
  FAIL("the study wrote no " << rows << " rows within 60 s");
}

/// Sends `signal` once rows are written; returns the wait status, showing how long the
/// process took to end.
int signalAfterRows(int pid, const fs::path& root, int signal) {
  awaitRows(root, 20);
  const auto sent = std::chrono::steady_clock::now();
  ::kill(pid, signal);
  const int status = waitForProcess(pid);
  MESSAGE("ended " << std::chrono::duration<double>(std::chrono::steady_clock::now() - sent).count()
                   << " s after signal " << signal);
  return status;
}

}  // namespace

TEST_SUITE("study signals") {
  TEST_CASE("SIGINT: ended by it, the rows done kept, the missing points named") {
    const fs::path root = scratchDir("study-sigint");
    // 100 x 201 points: minutes of work, stopped after its first rows.
    const int pid = startBeamrotor(root, studyArguments(99, "out"));
    const int status = signalAfterRows(pid, root, SIGINT);
    CHECK(WIFSIGNALED(status));
    CHECK(WTERMSIG(status) == SIGINT);
    const std::string log = fileContents(root / "log");
    CAPTURE(log);
    const auto summary = nlohmann::json::parse(fileContents(root / "out" / "summary.json"));
    CHECK(summary["partial"] == true);
    CHECK(summary["stopped_by"] == "SIGINT");
    const long long rows = lineCount(root / "out" / "study.csv") - 1;
    CHECK(rows >= 20);
    CHECK(summary["points"] == rows);
    CHECK(rows + summary["missing"]["count"].get<long long>() == 20100);
    CHECK(summary["missing"]["points"].back()[1] == 20099);
    CHECK(log.find("stopped by SIGINT") != std::string::npos);
    CHECK(log.find("--resume out") != std::string::npos);
    CHECK(temporaryOf(root).empty());
    fs::remove_all(root);
  }

  TEST_CASE("SIGTERM on two threads, then --resume: the uninterrupted table byte for byte") {
    const fs::path root = scratchDir("study-sigterm");
    // 41 x 201 points: twice what threads may solve ahead of the table (4096 rows), so the
    // signal, sent at row 20, leaves points missing.
    const ProcessResult whole = runBeamrotor(studyArguments(40, (root / "whole").string()));
    REQUIRE(whole.exitCode == 0);
    std::vector<std::string> arguments = studyArguments(40, "out");
    arguments.insert(arguments.end(), {"--threads", "2"});
    const int status = signalAfterRows(startBeamrotor(root, arguments), root, SIGTERM);
    CHECK(WIFSIGNALED(status));
    CHECK(WTERMSIG(status) == SIGTERM);
    const auto summary = nlohmann::json::parse(fileContents(root / "out" / "summary.json"));
    REQUIRE(summary["partial"] == true);
    CHECK(summary["stopped_by"] == "SIGTERM");
    arguments.back() = "1";
    arguments.insert(arguments.end(), {"--resume", "out"});
    const ProcessResult resumed = runBeamrotor(arguments, root);
    CAPTURE(resumed.err);
    CHECK(resumed.exitCode == 0);
    CHECK(resumed.out.find("resumed: ") != std::string::npos);
    CHECK(fileContents(root / "out" / "study.csv") == fileContents(root / "whole" / "study.csv"));
    fs::remove_all(root);
  }

  TEST_CASE("kill -9: the rows stay in the temporary directory, kept, named and resumed") {
    const fs::path root = scratchDir("study-sigkill");
    const ProcessResult whole = runBeamrotor(studyArguments(19, (root / "whole").string()));
    REQUIRE(whole.exitCode == 0);
    const int status = signalAfterRows(startBeamrotor(root, studyArguments(19, "out")), root,
                                       SIGKILL);
    CHECK(WIFSIGNALED(status));
    const fs::path left = temporaryOf(root);
    REQUIRE_FALSE(left.empty());
    const long long rows = lineCount(left / "study.csv") - 1;
    CHECK(rows >= 20);
    // Another study into the same directory keeps it, and says so.
    const ProcessResult other =
        runBeamrotor({"study", (problemsDir() / "pump_rod.yaml").string(), "--sweep",
                      "eta=0,0.4", "--out", "out"},
                     root);
    CHECK(other.exitCode == 0);
    CHECK(other.err.find("kept '") != std::string::npos);
    CHECK(other.err.find(left.filename().string()) != std::string::npos);
    CHECK(other.err.find("--resume") != std::string::npos);
    CHECK(fs::exists(left / "study.csv"));
    // --resume continues it into out/, which it was being written for, and then removes it.
    std::vector<std::string> arguments = studyArguments(19, "ignored");
    arguments.resize(arguments.size() - 2);  // no --out
    arguments.insert(arguments.end(), {"--resume", left.filename().string()});
    const ProcessResult resumed = runBeamrotor(arguments, root);
    CAPTURE(resumed.err);
    CHECK(resumed.exitCode == 0);
    CHECK(resumed.out.find("resumed: ") != std::string::npos);
    CHECK(fileContents(root / "out" / "study.csv") == fileContents(root / "whole" / "study.csv"));
    CHECK_FALSE(fs::exists(left));
    fs::remove_all(root);
  }
}

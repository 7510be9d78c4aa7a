#include "tests/problems/DeckTestSupport.hpp"

#include <doctest/doctest.h>
#include <signal.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <numbers>
#include <sstream>
#include <stdexcept>
#include <thread>

#include "problems/deck/DeckReader.hpp"
#include "problems/deck/parse/DeckSource.hpp"

namespace beamrotor::test {

std::vector<std::filesystem::path> shippedDecks() {
  std::vector<std::filesystem::path> decks;
  for (const auto& entry : std::filesystem::directory_iterator(problemsDir()))
    if (entry.path().extension() == ".yaml") decks.push_back(entry.path());
  std::sort(decks.begin(), decks.end());
  return decks;
}

std::string fileContents(const std::filesystem::path& file) {
  std::ifstream in(file, std::ios::binary);
  std::ostringstream s;
  s << in.rdbuf();
  return s.str();
}

std::vector<std::vector<std::string>> csvCells(const std::filesystem::path& file) {
  std::vector<std::vector<std::string>> rows;
  std::istringstream in(fileContents(file));
  for (std::string line; std::getline(in, line);) {
    if (!line.empty() && line[0] == '#') continue;  // the units line (CsvTable.hpp)
    std::vector<std::string> cells;
    std::istringstream fields(line + ',');  // the comma closes a last cell that is empty
    for (std::string cell; std::getline(fields, cell, ',');) cells.push_back(cell);
    rows.push_back(cells);
  }
  return rows;
}

std::size_t csvColumn(const std::vector<std::string>& header, const std::string& name) {
  const std::string quoted = '"' + name + '"';
  for (std::size_t k = 0; k < header.size(); ++k)
    if (header[k] == name || header[k] == quoted) return k;
  FAIL("no column " << name);
  return 0;
}

std::string shellQuoted(const std::string& s) {
  std::string out = "'";
  for (char c : s) out += c == '\'' ? std::string("'\\''") : std::string(1, c);
  return out + "'";
}

std::filesystem::path scratchDir(const std::string& name) {
  const auto dir = std::filesystem::temp_directory_path() /
                   ("beamrotor-deck-tests-" + std::to_string(getpid())) / name;
  std::filesystem::remove_all(dir);
  std::filesystem::create_directories(dir);
  return dir;
}

ProcessResult runBeamrotor(const std::vector<std::string>& arguments,
                           const std::filesystem::path& workingDir,
                           const std::vector<std::string>& environment) {
  static int counter = 0;
  const auto dir = scratchDir("process-" + std::to_string(++counter));
  const std::string where = shellQuoted(workingDir.string()), exe = shellQuoted(BEAMROTOR_EXE);
  const std::string out = shellQuoted((dir / "out").string()),
                    err = shellQuoted((dir / "err").string());
  std::string command = "cd " + where + " && env";
  for (const std::string& e : environment) command += ' ' + shellQuoted(e);
  command += " timeout -k 5 120 " + exe;
  for (const std::string& a : arguments) command += ' ' + shellQuoted(a);
  command += " >" + out + " 2>" + err;
  const int status = std::system(command.c_str());
  ProcessResult r;
  r.exitCode = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
  r.out = fileContents(dir / "out");
  r.err = fileContents(dir / "err");
  std::filesystem::remove_all(dir);
  return r;
}

int startBeamrotor(const std::filesystem::path& dir, const std::vector<std::string>& arguments) {
  const pid_t pid = fork();
  if (pid == 0) {
    if (chdir(dir.c_str()) != 0) _exit(127);
    if (!freopen("log", "w", stdout) || !freopen("log", "a", stderr)) _exit(127);
    signal(SIGINT, SIG_DFL);  // a background test run may have them ignored
    signal(SIGTERM, SIG_DFL);
    std::vector<char*> argv{const_cast<char*>(BEAMROTOR_EXE)};
    for (const std::string& a : arguments) argv.push_back(const_cast<char*>(a.c_str()));
    argv.push_back(nullptr);
    execv(BEAMROTOR_EXE, argv.data());
    _exit(127);
  }
  return pid;
}

int waitForProcess(int pid, double seconds) {
  const auto until = std::chrono::steady_clock::now() + std::chrono::duration<double>(seconds);
  int status = 0;
  while (waitpid(pid, &status, WNOHANG) == 0) {
    if (std::chrono::steady_clock::now() > until) {
      kill(pid, SIGKILL);
      waitpid(pid, &status, 0);
      FAIL("process " << pid << " still running after " << seconds << " s");
    }
    std::this_thread::sleep_for(std::chrono::milliseconds(5));
  }
  return status;
}

nlohmann::json analysisOfType(const nlohmann::json& results, const std::string& type) {
  nlohmann::json found;
  for (const auto& a : results["analyses"])
    if (a["type"] == type) found = a;
  return found;
}

nlohmann::json SolvedDeck::json(const std::string& file) const {
  return nlohmann::json::parse(text(file));
}

std::string SolvedDeck::text(const std::string& file) const {
  return fileContents(dir / file);
}

SolvedDeck solveShippedDeckToScratch(const std::string& deck, const std::string& scratch) {
  const auto out = scratchDir(scratch) / "out";
  SolvedDeck solved{runBeamrotor({"solve", "problems/" + deck, "--out", out.string()}), out};
  CAPTURE(solved.process.err);
  REQUIRE(solved.process.exitCode == 0);
  return solved;
}

StudyRequest shippedDeckRequest(const std::string& name, std::vector<std::string> sets) {
  StudyRequest r;
  r.deckPath = (problemsDir() / name).string();
  r.sets = std::move(sets);
  r.noSweep = true;
  return r;
}

Study solveShippedDeck(const std::string& name) {
  return solveStudyText(fileContents(problemsDir() / name), shippedDeckRequest(name));
}

double compressorRotorMass() {
  const double D = 0.09, L = 1.3, rho = 7850, Dd = 0.38, wd = 0.07;
  return rho * std::numbers::pi * D * D / 4 * L +
         2 * rho * std::numbers::pi * (Dd * Dd - D * D) / 4 * wd;
}

DeckError readingError(const std::string& text, const std::string& path) {
  try {
    readDeck(parseDeckText(text, path), {});
  } catch (const DeckError& e) {
    return e;
  }
  FAIL("no DeckError for:\n" << text);
  throw std::logic_error("not reached");
}

Study solveDeckText(const std::string& text, const std::string& path) {
  StudyRequest request;
  request.deckPath = path;
  return solveStudyText(text, request);
}

std::vector<const RunResult*> runsOf(const Study& study) {
  std::vector<const RunResult*> runs;
  if (study.run) runs.push_back(&*study.run);
  if (study.sweep)
    for (const RunResult& r : study.sweep->runs) runs.push_back(&r);
  return runs;
}

int checkAllPass(const Study& study) {
  int applied = 0;
  for (const RunResult* run : runsOf(study))
    for (const Check& c : run->checks) {
      CAPTURE(c.name);
      CAPTURE(c.computed);
      CAPTURE(c.reference);
      CHECK(c.pass());
      ++applied;
    }
  return applied;
}

double staticReaction(const RunResult& run, const std::string& support, Dof dof) {
  for (const AnalysisOutcome& a : run.analyses)
    if (staticsOf(a)) return staticsOf(a)->reaction(support, dof);
  throw std::invalid_argument("run of " + run.deckName + " has no static analysis");
}

double deckValue(const Deck& deck, const std::string& name) {
  for (const auto* list : {&deck.parameters, &deck.derived})
    for (const auto& [n, v] : *list)
      if (n == name) return v;
  throw std::invalid_argument(deck.path + " has no value named " + name);
}

}  // namespace beamrotor::test

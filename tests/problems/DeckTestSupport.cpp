#include "tests/problems/DeckTestSupport.hpp"

#include <unistd.h>

#include <algorithm>
#include <cstdlib>
#include <fstream>
#include <sstream>

namespace beamrotor::test {

std::vector<std::filesystem::path> shippedDecks() {
  std::vector<std::filesystem::path> decks;
  for (const auto& entry : std::filesystem::directory_iterator(problemsDir()))
    if (entry.path().extension() == ".yaml") decks.push_back(entry.path());
  std::sort(decks.begin(), decks.end());
  return decks;
}

namespace {

std::string shellQuoted(const std::string& s) {
  std::string out = "'";
  for (char c : s) out += c == '\'' ? std::string("'\\''") : std::string(1, c);
  return out + "'";
}

std::string slurp(const std::filesystem::path& p) {
  std::ifstream in(p, std::ios::binary);
  std::ostringstream s;
  s << in.rdbuf();
  return s.str();
}

}  // namespace

std::filesystem::path scratchDir(const std::string& name) {
  const auto dir = std::filesystem::temp_directory_path() /
                   ("beamrotor-deck-tests-" + std::to_string(getpid())) / name;
  std::filesystem::remove_all(dir);
  std::filesystem::create_directories(dir);
  return dir;
}

ProcessResult runBeamrotor(const std::vector<std::string>& arguments) {
  static int counter = 0;
  const auto dir = scratchDir("process-" + std::to_string(++counter));
  std::string command = "cd " + shellQuoted(BEAMROTOR_SOURCE_DIR) + " && " +
                        shellQuoted(BEAMROTOR_EXE);
  for (const std::string& a : arguments) command += " " + shellQuoted(a);
  command += " >" + shellQuoted((dir / "out").string()) + " 2>" + shellQuoted((dir / "err").string());
  const int status = std::system(command.c_str());
  ProcessResult r;
  r.exitCode = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
  r.out = slurp(dir / "out");
  r.err = slurp(dir / "err");
  std::filesystem::remove_all(dir);
  return r;
}

}  // namespace beamrotor::test

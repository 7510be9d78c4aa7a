#include "tests/hostile/HostileSupport.hpp"

#include <doctest/doctest.h>

#include <cstdlib>
#include <fstream>
#include <map>
#include <regex>
#include <sstream>

#include "problems/cli/App.hpp"

namespace beamrotor::test {

namespace fs = std::filesystem;

namespace {

std::string replaced(std::string text, const std::string& from, const std::string& to) {
  for (std::size_t at = text.find(from); at != std::string::npos; at = text.find(from, at))
    text.replace(at, from.size(), to), at += to.size();
  return text;
}

bool allowed(const std::string& relative, const std::vector<std::string>& mayChange) {
  for (const std::string& m : mayChange)
    if (relative == m || relative.rfind(m + "/", 0) == 0 || relative.rfind(m + ".tmp-", 0) == 0)
      return true;
  return false;
}

/// Every entry of the sandbox outside the paths a case may change: type and content.
std::map<std::string, std::string> snapshot(const fs::path& sandbox,
                                            const std::vector<std::string>& mayChange) {
  std::map<std::string, std::string> seen;
  for (auto it = fs::recursive_directory_iterator(sandbox);
       it != fs::recursive_directory_iterator(); ++it) {
    const std::string relative = it->path().lexically_relative(sandbox).generic_string();
    if (allowed(relative, mayChange)) {
      if (it->symlink_status().type() == fs::file_type::directory) it.disable_recursion_pending();
      continue;
    }
    const fs::file_type type = it->symlink_status().type();
    seen[relative] = type == fs::file_type::regular     ? "file:" + fileContents(it->path())
                     : type == fs::file_type::directory ? std::string("dir")
                                                        : "other:" + std::to_string(int(type));
  }
  return seen;
}

/// Files under the changeable paths whose text holds a NaN or an infinity as a number.
std::vector<std::string> filesWithNonFinite(const fs::path& sandbox,
                                            const std::vector<std::string>& mayChange) {
  static const std::regex nonFinite(R"((^|[\s,:\[])[-+]?(nan|inf|infinity)([\s,\]]|$))",
                                    std::regex::icase);
  std::vector<std::string> bad;
  for (const std::string& m : mayChange) {
    const fs::path root = sandbox / m;
    if (!fs::is_directory(root)) continue;
    for (const auto& entry : fs::recursive_directory_iterator(root)) {
      const std::string ext = entry.path().extension().string();
      if (!entry.is_regular_file() || (ext != ".json" && ext != ".csv")) continue;
      const std::string text = fileContents(entry.path());
      if (std::regex_search(text, nonFinite)) bad.push_back(entry.path().string());
    }
  }
  return bad;
}

/// Without charts, gnuplot is pointed at nothing (a warning, and no time spent drawing).
std::vector<std::string> gnuplotSetting(const HostileCase& c) {
  if (c.charts) return {};
  return {"BEAMROTOR_GNUPLOT=/nonexistent/gnuplot"};
}

/// The command line called in this process, in `dir` (restored after).
ProcessResult runInThisProcess(const std::vector<std::string>& arguments, const fs::path& dir,
                               bool charts) {
  const char* gnuplot = std::getenv("BEAMROTOR_GNUPLOT");
  const std::string saved = gnuplot ? gnuplot : "";
  if (!charts) setenv("BEAMROTOR_GNUPLOT", "/nonexistent/gnuplot", 1);
  const fs::path back = fs::current_path();
  fs::current_path(dir);
  std::vector<const char*> argv{"beamrotor"};
  for (const std::string& a : arguments) argv.push_back(a.c_str());
  std::ostringstream out, err;
  ProcessResult r;
  r.exitCode = beamrotor::cli::runCommandLine(int(argv.size()), argv.data(), out, err);
  fs::current_path(back);
  if (gnuplot)
    setenv("BEAMROTOR_GNUPLOT", saved.c_str(), 1);
  else
    unsetenv("BEAMROTOR_GNUPLOT");
  r.out = out.str();
  r.err = err.str();
  return r;
}

}  // namespace

std::string hostileBaseDeck(const std::string& title, const std::string& unit,
                            const std::string& check) {
  return "title: " + title + "\n" + kHostileBeam + R"(supports:
  - {name: left, at: start, fix: clamped}
loads:
  - {type: point, at: end, fy: -1000}
analyses:
  - {type: static, name: bend}
  - type: transient
    name: shake
    dt: 0.001
    end: 0.004
    record:
      - {name: tip, at: end, dof: uy}
      - {name: force, value: 2e5*tip, unit: )" +
         unit + R"(}
checks:
  - {name: )" +
         check + R"(, quantity: displacement end uy, reference: -0.0054325, tolerance: 0.01}
)";
}

std::string atField(const std::string& field) {
  return R"(^deck\.yaml:\d+:\d+: )" + field + ": ";
}

ProcessResult runHostileCase(const HostileCase& c) {
  static int counter = 0;
  const fs::path sandbox = scratchDir("hostile-" + std::to_string(++counter));
  if (!c.deck.empty()) std::ofstream(sandbox / "deck.yaml", std::ios::binary) << c.deck;
  if (c.setup) c.setup(sandbox);
  const auto before = snapshot(sandbox, c.mayChange);

  std::vector<std::string> arguments;
  for (const std::string& a : c.arguments)
    arguments.push_back(replaced(a, "{sandbox}", sandbox.string()));
  const ProcessResult r = c.process ? runBeamrotor(arguments, sandbox, gnuplotSetting(c))
                                    : runInThisProcess(arguments, sandbox, c.charts);

  CAPTURE(r.out);
  CAPTURE(r.err);
  CHECK(r.exitCode == c.exitCode);
  if (!c.message.empty()) CHECK(std::regex_search(r.err, std::regex(c.message)));
  // Nothing outside the changeable paths was touched (a payload's canary included).
  const auto after = snapshot(sandbox, c.mayChange);
  for (const auto& [path, content] : after) {
    CAPTURE(path);
    CHECK((before.count(path) == 1 && before.at(path) == content));
  }
  for (const auto& [path, content] : before) {
    CAPTURE(path);
    CHECK(after.count(path) == 1);
  }
  CHECK(filesWithNonFinite(sandbox, c.mayChange).empty());
  // A payload's canary, wherever a command would have made it (a relative path lands in the
  // directory gnuplot runs in, inside the results).
  for (const auto& entry : fs::recursive_directory_iterator(sandbox)) {
    CAPTURE(entry.path().string());
    CHECK(entry.path().filename() != "canary");
  }
  std::error_code ignored;
  fs::remove_all(sandbox, ignored);
  return r;
}

int runHostileCases(const std::vector<HostileCase>& cases) {
  int ran = 0;
  for (const HostileCase& c : cases) {
    CAPTURE(c.name);
    runHostileCase(c);
    ++ran;
  }
  return ran;
}

}  // namespace beamrotor::test

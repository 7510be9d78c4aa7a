// Running gnuplot (see Gnuplot.hpp): locating it, the SVG + PNG script frame, warnings. Text
// from a deck reaches the script only as inert string literals (gnuplotText, gnuplotFile), and
// gnuplot is started directly, without a shell.
#include "problems/output/files/Gnuplot.hpp"

#include <fcntl.h>
#include <spawn.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <atomic>
#include <cerrno>
#include <cstdlib>
#include <cstring>
#include <fstream>
#include <iostream>
#include <sstream>

#include "problems/deck/parse/PlainText.hpp"
#include "problems/output/files/FileWriting.hpp"

extern char** environ;

namespace beamrotor {

namespace {

namespace fs = std::filesystem;

bool isExecutable(const fs::path& p) {
  std::error_code ec;
  const auto status = fs::status(p, ec);
  return !ec && fs::is_regular_file(status) &&
         (status.permissions() & (fs::perms::owner_exec | fs::perms::group_exec |
                                  fs::perms::others_exec)) != fs::perms::none;
}

void warn(const std::string& message) {
  std::cerr << "beamrotor: warning: " << message << "\n";
}

/// gnuplot ends its error report with the message itself (after the command and a caret).
std::string lastMessageLine(const fs::path& file) {
  std::ifstream in(file);
  std::string message = "no message";
  for (std::string line; std::getline(in, line);)
    if (line.find_first_not_of(" \t^") != std::string::npos) message = line;
  return message;
}

/// Whether gnuplot finished writing an image: an SVG ends with its closing tag, a PNG with its
/// IEND chunk. A full device leaves them cut short (gnuplot does not notice).
enum class ImageState { absent, incomplete, complete };

ImageState imageState(const fs::path& p) {
  std::error_code ec;
  if (!fs::is_regular_file(p, ec)) return ImageState::absent;
  std::ifstream in(p, std::ios::binary);
  std::string tail(64, '\0');
  in.seekg(0, std::ios::end);
  const std::streamoff size = in.tellg();
  const std::streamoff start = std::max<std::streamoff>(0, size - std::streamoff(tail.size()));
  in.seekg(start);
  in.read(tail.data(), std::streamsize(tail.size()));
  tail.resize(std::size_t(in.gcount()));
  const bool complete =
      p.extension() == ".svg"
          ? tail.find_last_not_of(" \t\r\n") != std::string::npos &&
                tail.substr(0, tail.find_last_not_of(" \t\r\n") + 1).ends_with("</svg>")
          : tail.ends_with(std::string("IEND\xAE\x42\x60\x82", 8));
  return complete ? ImageState::complete : ImageState::incomplete;
}

/// "; the device has 12 kB free": what may explain an image cut short.
std::string spaceLeft(const fs::path& dir) {
  std::error_code ec;
  const fs::space_info space = fs::space(dir, ec);
  if (ec) return {};
  return "; the device has " + std::to_string(space.available / 1024) + " kB free";
}

/// Runs `gnuplot ./SCRIPT` in dir, stdin from /dev/null, stdout and stderr into dir/LOG;
/// returns its exit status (-1 when it could not be started or did not exit normally).
int runGnuplot(const fs::path& gnuplot, const fs::path& dir, const std::string& script,
               const std::string& log) {
  posix_spawn_file_actions_t actions;
  posix_spawn_file_actions_init(&actions);
  posix_spawn_file_actions_addchdir_np(&actions, dir.c_str());
  posix_spawn_file_actions_addopen(&actions, 0, "/dev/null", O_RDONLY, 0);
  posix_spawn_file_actions_addopen(&actions, 1, log.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
  posix_spawn_file_actions_adddup2(&actions, 1, 2);
  const std::string program = fs::absolute(gnuplot).string();
  // "./" keeps a script name from reading as an option (a name may start with '-').
  const std::string argument = "./" + script;
  char* const argv[] = {const_cast<char*>(program.c_str()), const_cast<char*>(argument.c_str()),
                        nullptr};
  pid_t child = 0;
  const int spawned = posix_spawn(&child, program.c_str(), &actions, nullptr, argv, environ);
  posix_spawn_file_actions_destroy(&actions);
  if (spawned != 0) return -1;
  int status = 0;
  while (waitpid(child, &status, 0) < 0)
    if (errno != EINTR) return -1;
  return WIFEXITED(status) ? WEXITSTATUS(status) : -1;
}

/// Text for a comment line: plain, and not ending in a backslash (which would continue the
/// comment onto the next line).
std::string gnuplotComment(const std::string& text) {
  std::string plain = plainText(text);
  while (!plain.empty() && plain.back() == '\\') plain.pop_back();
  return plain;
}

/// The script: the chart body drawn once per output format.
std::string script(const ChartScript& chart) {
  const std::string size = std::to_string(chart.width) + "," + std::to_string(chart.height);
  std::ostringstream s;
  s << "# " << gnuplotComment(chart.purpose) << "\n"
    << "# Written by beamrotor. Redraw it from this directory with: gnuplot "
    << gnuplotComment(chart.name) << ".gp\n"
    << chart.data << "do for [format in 'svg png'] {\n"
    << "  if (format eq 'svg') {\n"
    << "    set terminal svg size " << size
    << " dynamic enhanced font 'Sans,12' background rgb 'white'\n"
    << "  } else {\n"
    << "    if (strstrt(GPVAL_TERMINALS, ' pngcairo ') > 0) {\n"
    << "      set terminal pngcairo size " << size
    << " enhanced font 'Sans,10' background rgb 'white'\n"
    << "    } else {\n"
    << "      set terminal png size " << size << " enhanced background rgb 'white'\n"
    << "    }\n"
    << "  }\n"
    << "  set output " << gnuplotFile(chart.name) << ".'.'.format\n"
    << "  reset\n"
    << "  set datafile separator ','\n"
    << chart.body << "  set output\n"
    << "}\n";
  return s.str();
}

}  // namespace

std::optional<fs::path> findGnuplot() {
  const char* configured = std::getenv("BEAMROTOR_GNUPLOT");
  const std::string program = configured && *configured ? configured : "gnuplot";
  if (program.find('/') != std::string::npos)
    return isExecutable(program) ? std::optional<fs::path>(program) : std::nullopt;
  const char* path = std::getenv("PATH");
  std::istringstream dirs(path ? path : "");
  for (std::string dir; std::getline(dirs, dir, ':');)
    if (!dir.empty() && isExecutable(fs::path(dir) / program)) return fs::path(dir) / program;
  return std::nullopt;
}

bool drawChart(const fs::path& dir, const ChartScript& chart) {
  static std::atomic<bool> warnedMissing{false};
  const auto gnuplot = findGnuplot();
  if (!gnuplot) {
    if (!warnedMissing.exchange(true))
      warn("gnuplot not found (install gnuplot or set BEAMROTOR_GNUPLOT); charts skipped");
    return false;
  }
  const std::string name = confinedFileName(chart.name);
  const std::string scriptName = name + ".gp", logName = name + ".log";
  // The script is a file of ours like any other: failing to write it fails the run.
  writeFile(dir / scriptName, [&](std::ostream& out) { out << script(chart); });
  const int status = runGnuplot(*gnuplot, dir, scriptName, logName);
  const fs::path images[] = {dir / (name + ".svg"), dir / (name + ".png")};
  if (status == 0) {
    // gnuplot succeeded: an image cut short means the write failed, as for any other file.
    for (const fs::path& image : images)
      if (imageState(image) == ImageState::incomplete)
        throw std::runtime_error(
            writeFailure(image, 0, "gnuplot's output is incomplete" + spaceLeft(dir)));
    if (imageState(images[0]) == ImageState::complete &&
        imageState(images[1]) == ImageState::complete) {
      std::error_code ignored;
      fs::remove(dir / logName, ignored);
      return true;
    }
  }
  warn("gnuplot could not draw " + name + " (" +
       (status == -1 ? std::string("it could not be started") : lastMessageLine(dir / logName)) +
       "); see " + logName);
  return false;
}

std::string gnuplotText(const std::string& text) {
  // Plain text first: a line break (or any control character) would end the script line
  // inside the string and start a command of the deck's choosing.
  std::string escaped;
  for (char c : plainText(text)) {
    if (c == '_' || c == '^' || c == '@' || c == '&' || c == '~' || c == '{' || c == '}' ||
        c == '\\')
      escaped += '\\';
    escaped += c;
  }
  // gnuplot reads '' inside a single-quoted string as a quote, except at its start (where it
  // is an empty string): quotes are joined in as "'" instead, 'It'."'".'s'.
  std::string literal = "'";
  for (char c : escaped) literal += c == '\'' ? std::string("'.\"'\".'") : std::string(1, c);
  return literal + "'";
}

std::string confinedFileName(const std::string& file) {
  // Parts of letters, digits, '-', '_' and '.' (as fileStem makes them), joined by '/'.
  bool plain = !file.empty();
  std::size_t start = 0;
  while (plain && start <= file.size()) {
    const std::size_t end = std::min(file.find('/', start), file.size());
    const std::string part = file.substr(start, end - start);
    plain = !part.empty() && part != "." && part != ".." &&
            std::all_of(part.begin(), part.end(), [](char c) {
              return (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z') || (c >= '0' && c <= '9') ||
                     c == '-' || c == '_' || c == '.';
            });
    start = end + 1;
  }
  if (!plain)
    throw std::invalid_argument("chart file name '" + plainText(file) +
                                "' is not a plain relative name inside the results directory");
  return file;
}

std::string gnuplotFile(const std::string& file) {
  // "./" first: gnuplot reads a name starting with '-' or '+' as a special input.
  return "'./" + confinedFileName(file) + "'";
}

}  // namespace beamrotor

// Running gnuplot (see Gnuplot.hpp): locating it, the SVG + PNG script frame, warnings.
#include "problems/output/Gnuplot.hpp"

#include <sys/wait.h>

#include <atomic>
#include <cstdlib>
#include <fstream>
#include <iostream>
#include <sstream>

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

/// text inside single quotes for /bin/sh.
std::string shellQuoted(const std::string& text) {
  std::string out = "'";
  for (char c : text) out += c == '\'' ? std::string("'\\''") : std::string(1, c);
  return out + "'";
}

std::string singleQuoted(const std::string& text) {
  std::string out = "'";
  for (char c : text) out += c == '\'' ? std::string("''") : std::string(1, c);
  return out + "'";
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

bool nonEmptyFile(const fs::path& p) {
  std::error_code ec;
  return fs::is_regular_file(p, ec) && fs::file_size(p, ec) > 0;
}

/// The script: the chart body drawn once per output format.
std::string script(const ChartScript& chart) {
  const std::string size = std::to_string(chart.width) + "," + std::to_string(chart.height);
  std::ostringstream s;
  s << "# " << chart.purpose << "\n"
    << "# Written by beamrotor. Redraw it from this directory with: gnuplot " << chart.name
    << ".gp\n"
    << "do for [format in 'svg png'] {\n"
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
  try {
    const fs::path scriptFile = dir / (chart.name + ".gp"), log = dir / (chart.name + ".log");
    {
      std::ofstream out(scriptFile);
      out << script(chart);
      if (!out) throw std::runtime_error("cannot write " + scriptFile.string());
    }
    const std::string command =
        "cd " + shellQuoted(dir.string()) + " && " + shellQuoted(gnuplot->string()) + " " +
        shellQuoted(chart.name + ".gp") + " >" + shellQuoted(chart.name + ".log") + " 2>&1";
    const int status = std::system(command.c_str());
    const bool ran = status != -1 && WIFEXITED(status) && WEXITSTATUS(status) == 0;
    const bool drawn =
        nonEmptyFile(dir / (chart.name + ".svg")) && nonEmptyFile(dir / (chart.name + ".png"));
    if (ran && drawn) {
      fs::remove(log);
      return true;
    }
    warn("gnuplot could not draw " + chart.name + " (" + lastMessageLine(log) + "); see " +
         chart.name + ".log");
  } catch (const std::exception& e) {
    warn("chart " + chart.name + " skipped: " + e.what());
  }
  return false;
}

std::string gnuplotText(const std::string& text) {
  std::string escaped;
  for (char c : text) {
    if (c == '_' || c == '^' || c == '@' || c == '&' || c == '~' || c == '{' || c == '}' ||
        c == '\\')
      escaped += '\\';
    escaped += c;
  }
  return singleQuoted(escaped);
}

std::string gnuplotFile(const std::string& file) {
  return singleQuoted(file);
}

}  // namespace beamrotor

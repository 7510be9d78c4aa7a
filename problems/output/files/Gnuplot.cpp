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
#include "problems/output/files/ChartBatch.hpp"
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

/// Starts `gnuplot ./A.gp ./B.gp ...` in dir (gnuplot draws the scripts one after another and
/// stops at the first that fails), stdin from /dev/null, stdout and stderr into dir/LOG;
/// returns the child's id, or -1 when it could not be started.
pid_t startGnuplot(const fs::path& gnuplot, const fs::path& dir,
                   const std::vector<std::string>& scripts, const std::string& log) {
  posix_spawn_file_actions_t actions;
  posix_spawn_file_actions_init(&actions);
  posix_spawn_file_actions_addchdir_np(&actions, dir.c_str());
  posix_spawn_file_actions_addopen(&actions, 0, "/dev/null", O_RDONLY, 0);
  posix_spawn_file_actions_addopen(&actions, 1, log.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
  posix_spawn_file_actions_adddup2(&actions, 1, 2);
  const std::string program = fs::absolute(gnuplot).string();
  // "./" keeps a script name from reading as an option (a name may start with '-').
  std::vector<std::string> arguments;
  for (const std::string& script : scripts) arguments.push_back("./" + script);
  std::vector<char*> argv{const_cast<char*>(program.c_str())};
  for (std::string& argument : arguments) argv.push_back(argument.data());
  argv.push_back(nullptr);
  pid_t child = 0;
  const int spawned = posix_spawn(&child, program.c_str(), &actions, nullptr, argv.data(), environ);
  posix_spawn_file_actions_destroy(&actions);
  return spawned == 0 ? child : -1;
}

/// The exit status of a started gnuplot (-1 when it was not started or did not exit normally).
int exitStatus(pid_t child) {
  if (child < 0) return -1;
  int status = 0;
  while (waitpid(child, &status, 0) < 0)
    if (errno != EINTR) return -1;
  return WIFEXITED(status) ? WEXITSTATUS(status) : -1;
}

/// The images a chart named `name` becomes in `format`.
std::vector<fs::path> imagesOf(const fs::path& dir, const std::string& name, ChartFormat format) {
  std::vector<fs::path> images;
  if (format == ChartFormat::svg || format == ChartFormat::both)
    images.push_back(dir / (name + ".svg"));
  if (format == ChartFormat::png || format == ChartFormat::both)
    images.push_back(dir / (name + ".png"));
  return images;
}

/// The worst state among a chart's images: absent when any is missing, else incomplete when
/// any is cut short.
ImageState chartState(const std::vector<fs::path>& images) {
  ImageState worst = ImageState::complete;
  for (const fs::path& image : images) {
    const ImageState state = imageState(image);
    if (state == ImageState::absent) return state;
    if (state == ImageState::incomplete) worst = state;
  }
  return worst;
}

/// What drawing a chart costs, roughly, in bytes of data: gnuplot's start and the image's
/// drawing and encoding, about what reading 200 kB costs, plus the data files its script reads
/// (each once: a panel that reads a file again reads only its own rows, `every`).
std::uintmax_t drawingCost(const fs::path& dir, const std::string& body) {
  constexpr std::uintmax_t kEachChart = 200000;
  std::uintmax_t cost = kEachChart + body.size();
  std::vector<std::string> read;
  for (std::size_t at = body.find("'./"); at != std::string::npos; at = body.find("'./", at + 1)) {
    const std::size_t end = body.find('\'', at + 3);
    if (end == std::string::npos) break;
    const std::string file = body.substr(at + 3, end - at - 3);
    if (std::find(read.begin(), read.end(), file) != read.end()) continue;
    read.push_back(file);
    std::error_code ec;
    const std::uintmax_t size = fs::file_size(dir / file, ec);
    if (!ec) cost += size;
  }
  return cost;
}

/// The charts (indices) split into at most `parts` shares of about equal cost: the dearest
/// chart first into the cheapest share. Each share keeps the charts' own order.
std::vector<std::vector<std::size_t>> shares(const std::vector<std::uintmax_t>& costs, int parts) {
  std::vector<std::size_t> order(costs.size());
  for (std::size_t i = 0; i < order.size(); ++i) order[i] = i;
  std::stable_sort(order.begin(), order.end(),
                   [&](std::size_t a, std::size_t b) { return costs[a] > costs[b]; });
  const std::size_t count = std::min<std::size_t>(std::size_t(std::max(parts, 1)), costs.size());
  std::vector<std::vector<std::size_t>> split(count);
  std::vector<std::uintmax_t> load(count, 0);
  for (std::size_t chart : order) {
    const std::size_t cheapest =
        std::size_t(std::min_element(load.begin(), load.end()) - load.begin());
    split[cheapest].push_back(chart);
    load[cheapest] += costs[chart];
  }
  for (auto& share : split) std::sort(share.begin(), share.end());
  return split;
}

/// Text for a comment line: plain, and not ending in a backslash (which would continue the
/// comment onto the next line).
std::string gnuplotComment(const std::string& text) {
  std::string plain = plainText(text);
  while (!plain.empty() && plain.back() == '\\') plain.pop_back();
  return plain;
}

/// gnuplot's list of the formats to draw.
std::string formatList(ChartFormat format) {
  switch (format) {
    case ChartFormat::svg:
      return "'svg'";
    case ChartFormat::both:
      return "'svg png'";
    default:
      return "'png'";
  }
}

/// The script: the chart body drawn once per output format. It starts from gnuplot's defaults
/// (`reset session`, the encoding too), so that one gnuplot drawing several scripts in turn
/// draws each as a gnuplot of its own would.
std::string script(const ChartScript& chart, ChartFormat format) {
  const std::string size = std::to_string(chart.width) + "," + std::to_string(chart.height);
  std::ostringstream s;
  s << "# " << gnuplotComment(chart.purpose) << "\n"
    << "# Written by beamrotor. Redraw it from this directory with: gnuplot "
    << gnuplotComment(chart.name) << ".gp\n"
    << "reset session\n"
    << chart.data
    << "do for [format in " << formatList(format) << "] {\n"
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
    << "  set encoding default\n"
    << "  set datafile separator ','\n"
    << chart.body << "  set output\n"
    << "}\n";
  return s.str();
}

/// One gnuplot process's share of the charts, in drawing order.
struct GnuplotRun {
  std::vector<std::size_t> charts;
  pid_t child = -1;
};

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
  if (ChartBatch* batch = ChartBatch::active()) return batch->add(dir, chart);
  return drawCharts(dir, {chart}, ChartFormat::both, 1) == 1;
}

int drawCharts(const fs::path& dir, const std::vector<ChartScript>& charts, ChartFormat format,
               int processes) {
  if (format == ChartFormat::none || charts.empty()) return 0;
  std::vector<std::string> names;
  for (const ChartScript& chart : charts) names.push_back(confinedFileName(chart.name));
  static std::atomic<bool> warnedMissing{false};
  const auto gnuplot = findGnuplot();
  if (!gnuplot) {
    if (!warnedMissing.exchange(true))
      warn("gnuplot not found (install gnuplot or set BEAMROTOR_GNUPLOT); charts skipped");
    return 0;
  }
  // The scripts are files of ours like any other: failing to write one fails the run. An
  // image left from an earlier drawing would pass for this one's.
  std::vector<std::uintmax_t> costs;
  for (std::size_t i = 0; i < charts.size(); ++i) {
    writeFile(dir / (names[i] + ".gp"),
              [&](std::ostream& out) { out << script(charts[i], format); });
    std::error_code ignored;
    for (const fs::path& image : imagesOf(dir, names[i], ChartFormat::both))
      fs::remove(image, ignored);
    costs.push_back(drawingCost(dir, charts[i].body));
  }
  std::vector<GnuplotRun> runs;
  for (std::vector<std::size_t>& share : shares(costs, processes)) runs.push_back({share, -1});
  int drawn = 0;
  while (!runs.empty()) {
    for (GnuplotRun& run : runs) {
      std::vector<std::string> scripts;
      for (std::size_t chart : run.charts) scripts.push_back(names[chart] + ".gp");
      run.child = startGnuplot(*gnuplot, dir, scripts, names[run.charts.front()] + ".log");
    }
    std::vector<GnuplotRun> again;  // the charts after one gnuplot failed on
    for (GnuplotRun& run : runs) {
      const int status = exitStatus(run.child);
      const std::string log = names[run.charts.front()] + ".log";
      bool stopped = false, logKept = false;
      for (std::size_t k = 0; k < run.charts.size() && !stopped; ++k) {
        const std::size_t chart = run.charts[k];
        const ImageState state = chartState(imagesOf(dir, names[chart], format));
        if (state == ImageState::complete) {
          ++drawn;
          continue;
        }
        if (state == ImageState::incomplete && status == 0) {
          // gnuplot succeeded: an image cut short means the write failed, as for any file.
          for (const fs::path& image : imagesOf(dir, names[chart], format))
            if (imageState(image) == ImageState::incomplete)
              throw std::runtime_error(
                  writeFailure(image, 0, "gnuplot's output is incomplete" + spaceLeft(dir)));
        }
        const std::string own = names[chart] + ".log";
        std::error_code ignored;
        if (own == log)
          logKept = true;
        else
          fs::copy_file(dir / log, dir / own, fs::copy_options::overwrite_existing, ignored);
        warn("gnuplot could not draw " + names[chart] + " (" +
             (run.child < 0 ? std::string("it could not be started") : lastMessageLine(dir / own)) +
             "); see " + own);
        // gnuplot stops at the script that fails: the rest of its share is drawn anew.
        stopped = status != 0;
        if (stopped && k + 1 < run.charts.size())
          again.push_back({{run.charts.begin() + std::ptrdiff_t(k) + 1, run.charts.end()}, -1});
      }
      std::error_code ignored;
      if (!logKept) fs::remove(dir / log, ignored);
    }
    runs = std::move(again);
  }
  return drawn;
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

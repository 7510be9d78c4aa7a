// Fixtures for the writer tests: a solved cantilever as a RunResult (the deck runner's
// contract, filled by hand), a scratch directory, readers for what the writers wrote, and a
// stand-in for gnuplot that records its starts (RecordedCharts).
#pragma once

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <memory>
#include <nlohmann/json.hpp>
#include <optional>
#include <random>
#include <sstream>
#include <string>
#include <vector>

#include "fem/modal/Modal.hpp"
#include "fem/static/Static.hpp"
#include "problems/run/RunResult.hpp"
#include "tests/Helpers.hpp"

namespace beamrotor::test {

/// A clamped cantilever along x, tip force -P along uy: the closed forms of beam theory.
struct Cantilever {
  double L = 2.0;     ///< m
  double P = 1500.0;  ///< N, pointing along -uy
  double D = 0.05;    ///< m, solid circle
  int elements = 4;
  std::shared_ptr<const Section> section = steelCircle(D);
  double EI() const { return section->EIz(); }
  /// Closed-form deflection and slope of the loaded cantilever at x (both negative).
  double deflection(double x) const { return -P * x * x * (3 * L - x) / (6 * EI()); }
  double slope(double x) const { return -P * x * (2 * L - x) / (2 * EI()); }
};

/// The cantilever solved statically ("tip") and, when `modes` > 0, for its first modes
/// ("modes"), packed as the deck runner would pack it.
inline RunResult cantileverRun(const Cantilever& c, int modes = 0) {
  auto model = std::make_shared<Model>();
  const Line line = uniformBeam(*model, c.L, c.section, c.elements);
  clamp(*model, "root", line.nodes.front(), DofSet::planar());
  model->addLoad({line.nodes.back(), Dof::uy, -c.P});

  RunResult run;
  run.deckPath = "tests/cantilever.yaml";
  run.deckName = "cantilever";
  run.parameters = {{"P", c.P}, {"L", c.L}};
  run.dimension = "planar";
  AnalysisOutcome statics{"static", "tip", StaticOutcome{solveStatic(*model), {}}, {}};
  const double tip = staticsOf(statics)->displacement(line.nodes.back(), dofIndex(Dof::uy));
  run.analyses.push_back(std::move(statics));
  if (modes > 0) run.analyses.push_back({"modal", "modes", solveModes(*model, {modes, 0}), {}});
  run.checks.push_back(
      {"tip deflection", tip, c.deflection(c.L), 1e-9, "displacement end uy", std::nullopt, ""});
  run.model = std::move(model);
  run.seconds = 0.01;
  return run;
}

/// A fresh directory path under the system's temp directory, removed with everything in it
/// (and any sibling the writers left) when the test ends.
class ScratchDir {
 public:
  ScratchDir() {
    std::random_device entropy;
    root_ = std::filesystem::temp_directory_path() /
            ("beamrotor-output-test-" + std::to_string(entropy()));
    std::filesystem::create_directories(root_);
  }
  ~ScratchDir() {
    std::error_code ignored;
    std::filesystem::remove_all(root_, ignored);
  }
  /// A path inside the scratch directory (not created).
  std::filesystem::path operator/(const std::string& name) const { return root_ / name; }
  /// Names of the entries directly inside the scratch directory.
  std::vector<std::string> entries() const {
    std::vector<std::string> names;
    for (const auto& e : std::filesystem::directory_iterator(root_))
      names.push_back(e.path().filename().string());
    return names;
  }

 private:
  std::filesystem::path root_;
};

/// Sets an environment variable for one scope.
class ScopedEnvironment {
 public:
  ScopedEnvironment(const char* name, const char* value) : name_(name) {
    if (const char* old = std::getenv(name)) old_ = old;
    setenv(name, value, 1);
  }
  ~ScopedEnvironment() {
    if (old_)
      setenv(name_, old_->c_str(), 1);
    else
      unsetenv(name_);
  }
  ScopedEnvironment(const ScopedEnvironment&) = delete;
  ScopedEnvironment& operator=(const ScopedEnvironment&) = delete;

 private:
  const char* name_;
  std::optional<std::string> old_;
};

inline std::string readText(const std::filesystem::path& file) {
  std::ifstream in(file);
  std::ostringstream s;
  s << in.rdbuf();
  return s.str();
}

inline nlohmann::json readJson(const std::filesystem::path& file) {
  std::ifstream in(file);
  return nlohmann::json::parse(in);
}

/// A numeric CSV file: its header cells and rows of numbers (no quoted fields).
struct NumericCsv {
  std::vector<std::string> header;
  std::vector<std::vector<double>> rows;
  /// Index of the header cell `name`; -1 when absent.
  int column(const std::string& name) const {
    for (std::size_t c = 0; c < header.size(); ++c)
      if (header[c] == name) return int(c);
    return -1;
  }
};

inline NumericCsv readNumericCsv(const std::filesystem::path& file) {
  std::ifstream in(file);
  NumericCsv csv;
  std::string line;
  const auto split = [](const std::string& text) {
    std::vector<std::string> cells;
    std::istringstream s(text);
    for (std::string cell; std::getline(s, cell, ',');) cells.push_back(cell);
    return cells;
  };
  if (std::getline(in, line)) csv.header = split(line);
  while (std::getline(in, line)) {
    if (!line.empty() && line[0] == '#') continue;  // the units line (CsvTable.hpp)
    std::vector<double> row;
    for (const std::string& cell : split(line)) row.push_back(std::stod(cell));
    csv.rows.push_back(row);
  }
  return csv;
}

/// A stand-in for gnuplot: records each start (its arguments, one line) in `record`, and for
/// each script ./NAME.gp draws a complete NAME.png, except for a script named `failing`, where
/// it stops with gnuplot's exit status 1 and its kind of message, as gnuplot does.
inline std::filesystem::path recordingGnuplot(const std::filesystem::path& dir, const std::filesystem::path& record,
                          const std::string& failing = "") {
  const std::filesystem::path file = dir / "gnuplot";
  std::ofstream(file) << "#!/bin/sh\n"
                      << "echo \"$*\" >> '" << record.string() << "'\n"
                      << "for script in \"$@\"; do\n"
                      << "  name=${script#./}; name=${name%.gp}\n"
                      << "  if [ \"$name\" = '" << failing << "' ]; then\n"
                      << "    echo \"$script line 3: undefined function: foo\" >&2; exit 1\n"
                      << "  fi\n"
                      << "  printf 'x\\000\\000\\000\\000IEND\\256B`\\202' > \"$name.png\"\n"
                      << "done\n";
  std::filesystem::permissions(file, std::filesystem::perms::owner_all);
  return file;
}

inline std::filesystem::path gnuplotToolsDir(const ScratchDir& scratch) {
  const std::filesystem::path dir = scratch / "tools";
  std::filesystem::create_directories(dir);
  return dir;
}

/// A charts directory in a scratch directory, drawn by recordingGnuplot (its starts recorded
/// in `record`; a script named `failing` fails) for as long as this lives.
struct RecordedCharts {
  explicit RecordedCharts(const std::string& failing = "")
      : dir(makeDir(scratch / "charts")),
        record(scratch / "record.txt"),
        gnuplot("BEAMROTOR_GNUPLOT",
                recordingGnuplot(gnuplotToolsDir(scratch), record, failing).c_str()) {}

  static std::filesystem::path makeDir(const std::filesystem::path& dir) {
    std::filesystem::create_directories(dir);
    return dir;
  }

  ScratchDir scratch;
  const std::filesystem::path dir, record;
  const ScopedEnvironment gnuplot;
};

}  // namespace beamrotor::test

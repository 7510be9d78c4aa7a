#include "problems/cli/Commands.hpp"

#include <cstdio>
#include <filesystem>
#include <fstream>
#include <memory>
#include <optional>

#include "fem/timing/Stopwatch.hpp"
#include "problems/cli/ExitCodes.hpp"
#include "problems/cli/PeakSummary.hpp"
#include "problems/cli/Guarded.hpp"
#include "problems/cli/Progress.hpp"
#include "problems/cli/Summary.hpp"
#include "problems/deck/parse/DeckError.hpp"
#include "problems/deck/parse/Units.hpp"
#include "problems/output/files/AtomicDirectory.hpp"
#include "problems/output/files/FileWriting.hpp"
#include "problems/output/structure/MatrixExport.hpp"
#include "problems/output/Output.hpp"

namespace beamrotor::cli {

namespace {

namespace fs = std::filesystem;

Study solveWithProgress(const StudyRequest& request, std::ostream& err) {
  std::unique_ptr<ProgressBar> shown;
  return solveStudy(request, [&](int done, int total) {
    if (!shown) shown = std::make_unique<ProgressBar>(err, ProgressBar::wanted(total));
    shown->update(done, total);
  });
}

/// The runs of a study with a label each ("eta = 0.4" in a sweep, empty otherwise).
/// The runs of s, and for a sweep each run's label ("L = 1200 mm": the value in `units`).
std::pair<std::vector<const RunResult*>, std::vector<std::string>> runsOf(
    const Study& s, const OutputUnits& units) {
  std::vector<const RunResult*> runs;
  std::vector<std::string> labels;
  if (s.run) {
    runs.push_back(&*s.run);
    labels.emplace_back();
  } else {
    for (std::size_t i = 0; i < s.sweep->runs.size(); ++i) {
      runs.push_back(&s.sweep->runs[i]);
      labels.push_back(s.sweep->parameter + " = " +
                       valueText(s.sweep->values[i], s.sweep->unit, units));
    }
  }
  return {runs, labels};
}

/// --export-matrices: the model of a single run into dir, of each sweep run into dir/run-<k>
/// (k from 1, in sweep order).
void exportStudyMatrices(const Study& s, const std::filesystem::path& dir) {
  if (s.run) {
    exportMatrices(*s.run->model, dir);
    return;
  }
  for (std::size_t k = 0; k < s.sweep->runs.size(); ++k)
    exportMatrices(*s.sweep->runs[k].model, dir / ("run-" + std::to_string(k + 1)));
}

void printHeader(std::ostream& out, const Study& s, const StudyRequest& request,
                 const OutputUnits& units) {
  out << "beamrotor " << BEAMROTOR_VERSION << ": " << s.deck.path;
  if (!s.deck.title.empty()) out << " (" << s.deck.title << ")";
  out << "\n";
  out << "parameters:";
  if (s.deck.parameters.empty()) out << " (none)";
  const char* separator = " ";
  for (const auto& [name, value] : s.deck.parameters) {
    const bool swept = s.sweep && s.sweep->parameter == name;
    // In SI with its unit, or in the user's unit of its quantity; a bare one as written.
    std::string unit;
    for (const auto& [named, dimension] : s.deck.dimensions)
      if (named == name) unit = siUnitOf(dimension);
    const OutputUnits::Shown shown = units.valueIn(unit, {1, unit});
    out << separator << name << " = ";
    if (swept)
      out << "swept" << (shown.unit.empty() ? "" : " (" + shown.unit + ")");
    else
      out << formatValue(value * shown.factor) << (shown.unit.empty() ? "" : " " + shown.unit);
    separator = ", ";
  }
  out << "\n";
  if (!request.formulation.empty())
    out << "formulation: " << request.formulation << " for every segment (--formulation)\n";
}

}  // namespace

int solveCommand(const SolveOptions& options, std::ostream& out, std::ostream& err) {
  return guarded(err, [&] {
    Stopwatch clock;
    // 1. Read and solve everything before writing anything: a failure leaves no output.
    const Study s = solveWithProgress(options.study, err);
    const double solveSeconds = clock.lap();

    // 2. Write the outputs.
    const std::filesystem::path dir = options.outDir.empty()
                                          ? std::filesystem::path("out") / s.deck.stem
                                          : std::filesystem::path(options.outDir);
    const fs::path matricesDir = options.exportMatrices && !options.exportMatrices->empty()
                                     ? fs::path(*options.exportMatrices)
                                     : dir / "matrices";
    // Matrices inside the results directory are written and replaced with it; elsewhere they
    // get an atomic directory of their own.
    const fs::path inResults =
        matricesDir.lexically_normal().lexically_relative(dir.lexically_normal());
    const bool inside = options.exportMatrices && !inResults.empty() &&
                        *inResults.begin() != ".." && inResults != ".";
    AlsoWrite also;
    if (inside)
      also = [&](const fs::path& temporary) { exportStudyMatrices(s, temporary / inResults); };
    const OutputChoices choices = chooseOutput(s.deck.output, options.output);
    std::string writeError;
    std::optional<PreparedRun> prepared;  // the run's extremes, computed once for the summary too
    try {
      if (s.run) {
        prepared = prepareRun(*s.run, choices);
        writePreparedRun(*prepared, dir, choices, also);
      } else
        writeSweepOutputs(*s.sweep, dir, choices, also);
      if (options.exportMatrices && !inside)
        writeDirectoryAtomically(
            matricesDir, [&](const fs::path& temporary) { exportStudyMatrices(s, temporary); });
    } catch (const std::exception& e) {
      writeError = e.what();
    }
    const double writeSeconds = clock.lap();

    // 3. The summary.
    printHeader(out, s, options.study, choices.units);
    if (s.run)
      printRunResults(out, s.deck, *s.run, prepared ? &prepared->extremes : nullptr,
                      choices.units);
    else
      printSweepResults(out, s.deck, *s.sweep, choices.units);
    printSweepPeaks(out, s, options.study.deckPath, choices.units);
    const auto [runs, labels] = runsOf(s, choices.units);
    const int failed = printChecks(out, s.deck, runs, labels, choices.units);
    char times[96];
    std::snprintf(times, sizeof times, "time: %.3f s (solve %.3f s, write %.3f s)\n",
                  solveSeconds + writeSeconds, solveSeconds, writeSeconds);
    out << times;
    if (failed > 0)
      out << "warning: " << failed << " check(s) FAILED (beamrotor check exits non-zero)\n";
    if (!writeError.empty()) {
      out << "results: not written\n";
      err << dir.string() << ": cannot write the results: " << writeError << "\n";
      return int(kSolveFailure);
    }
    out << "results: " << dir.string() << "/\n";
    if (options.exportMatrices) out << "matrices: " << matricesDir.string() << "/\n";
    return int(kOk);
  });
}

int checkCommand(const StudyRequest& request, std::ostream& out, std::ostream& err,
                 const OutputUnits& units) {
  return guarded(err, [&] {
    const Study s = solveWithProgress(request, err);
    const OutputUnits shown = s.deck.output.units.overlaid(units);
    printHeader(out, s, request, shown);
    const auto [runs, labels] = runsOf(s, shown);
    const int failed = printChecks(out, s.deck, runs, labels, shown);
    return int(failed > 0 ? kChecksFailed : kOk);
  });
}

int benchCommand(const BenchOptions& options, const std::string& jsonPath, std::ostream& out,
                 std::ostream& err) {
  BenchReport report;
  try {
    report = runBench(options);
  } catch (const std::invalid_argument& e) {
    err << "beamrotor bench: " << e.what() << "\n";
    return kInputError;
  } catch (const std::runtime_error& e) {  // --export could not be written
    err << "beamrotor bench: " << e.what() << "\n";
    return kSolveFailure;
  }
  out << benchTable(report);
  if (!jsonPath.empty()) {
    try {
      const std::string text = benchJson(report);
      writeFileAtomically(jsonPath, [&](std::ostream& json) { json << text << "\n"; });
    } catch (const std::exception& e) {
      err << "beamrotor bench: " << e.what() << "\n";
      return kSolveFailure;
    }
    out << "json: " << jsonPath << "\n";
  }
  return kOk;
}

}  // namespace beamrotor::cli

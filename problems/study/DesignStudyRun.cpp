#include "problems/study/DesignStudyRun.hpp"

#include <signal.h>

#include <cerrno>
#include <fstream>
#include <limits>
#include <optional>
#include <sstream>

#include "fem/timing/Stopwatch.hpp"
#include "problems/deck/DeckReader.hpp"
#include "problems/deck/structure/FormulationOption.hpp"
#include "problems/output/files/AtomicDirectory.hpp"
#include "problems/output/files/FileWriting.hpp"
#include "problems/output/files/Interruption.hpp"
#include "problems/output/Output.hpp"
#include "problems/study/DesignPoints.hpp"
#include "problems/study/StudyResume.hpp"
#include "problems/study/StudySummary.hpp"
#include "problems/study/StudyTable.hpp"

namespace beamrotor {

namespace {

namespace fs = std::filesystem;

/// What a killed study's temporary directory holds, for the run that finds it (see
/// writeDirectoryAtomically).
constexpr const char* kResumableNote =
    "the rows of a design study that did not finish; `beamrotor study` with the same deck "
    "and options and `--resume` naming this directory continues it (or remove it yourself)";

std::string deckFileText(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  std::ostringstream text;
  text << in.rdbuf();
  return text.str();
}

/// The plan: the deck read once with the overrides, its study, what every point shares.
StudyPlan readPlan(const DesignStudyRequest& request) {
  const DeckSource source = loadDeckFile(request.deckPath);  // refuses what is not a deck
  std::vector<ParameterOverride> overrides;
  for (const std::string& s : request.sets) overrides.push_back(parseOverride(s, source.path));
  Deck deck = readDeck(source, overrides);
  if (!request.formulation.empty()) applyFormulationOption(request.formulation, deck);
  DesignStudySpec spec = readDesignStudy(source, deck, request.study);
  for (const StudyParameter& p : spec.parameters)
    if (findOverride(overrides, p.name))
      throw DeckError(source.path, p.place, "'" + p.name + "' is both set (--set) and varied");
  StudyPlan plan = makeStudyPlan(source.path, deckFileText(request.deckPath), deck,
                                 std::move(overrides), request.formulation, std::move(spec));
  plan.lean = !request.fullPath;
  return plan;
}

bool stopAsked() {
  return pendingInterruption() != 0;
}

std::string signalName(int signal) {
  return signal == SIGINT ? "SIGINT" : signal == SIGTERM ? "SIGTERM" : signal == SIGHUP ? "SIGHUP"
                                                                                     : "a signal";
}

/// Writes results with `write` into `dir`, unless the study is stopping (its rows are what
/// counts then): a signal arriving meanwhile is taken on and the half-written directory
/// removed. False when nothing was written.
bool unlessStopping(const fs::path& dir, const std::function<void()>& write) {
  if (stopAsked()) return false;
  try {
    write();
    return true;
  } catch (const Interrupted&) {
    acknowledgeInterruption();
    std::error_code ignored;
    fs::remove_all(dir, ignored);
    return false;
  }
}

Json missingJson(const PointRanges& missing) {
  Json runs = Json::array();
  for (const PointRanges::Run& r : missing.runs()) runs.push_back({r.first, r.last});
  return Json{{"count", missing.size()}, {"points", runs}};
}

/// study.csv: the rows of a resumed study and the rows solved here, merged in point order,
/// each written through at once.
class TableWriter {
 public:
  TableWriter(std::ostream& csv, fs::path file, StudySummary& summary,
              StudyResumption* resumed, const StudyProgress& progress, long long total)
      : csv_(csv), file_(std::move(file)), summary_(summary), resumed_(resumed),
        progress_(progress), total_(total) {
    readStored();
  }
  /// A row solved here, after the stored rows before it.
  void solved(const StudyRow& row) {
    storedBefore(row.index);
    put(studyCsvRow(row), row);
  }
  /// The stored rows before point `index` (all that are left, by default).
  void storedBefore(long long index = std::numeric_limits<long long>::max()) {
    while (haveStored_ && stored_.index < index) {
      put(storedLine_, stored_);
      if (onStored) onStored(stored_);
      ++resumedRows;
      readStored();
    }
  }
  const PointRanges& written() const { return written_; }
  long long resumedRows = 0;
  std::function<void(const StudyRow&)> onStored;  ///< called for each stored row written

 private:
  void readStored() { haveStored_ = resumed_ && resumed_->nextRow(storedLine_, stored_); }
  void put(const std::string& line, const StudyRow& row) {
    csv_ << line;
    csv_.flush();  // through to the system now: the row outlives the process being killed
    if (!csv_) throw std::runtime_error(writeFailure(file_, errno));
    summary_.add(row);
    written_.append(row.index);
    if (progress_) progress_(written_.size(), total_);
  }
  std::ostream& csv_;
  fs::path file_;
  StudySummary& summary_;
  StudyResumption* resumed_;
  const StudyProgress& progress_;
  long long total_;
  PointRanges written_;
  bool haveStored_ = false;
  std::string storedLine_;
  StudyRow stored_;
};

}  // namespace

DesignStudyOutcome runDesignStudy(const DesignStudyRequest& request,
                                  const StudyProgress& progress) {
  Stopwatch clock;
  const StudyPlan plan = readPlan(request);
  const DesignPoints points(plan.spec);
  DesignStudyOutcome outcome;
  outcome.threads = request.threads;
  DeckOutput commandLine;
  commandLine.units = request.units;
  const OutputChoices worstChoices = chooseOutput(plan.output, commandLine);
  outcome.units = worstChoices.units;
  if (!isStudyManager()) {  // an MPI rank other than 0: solve what rank 0 hands out
    const DeferredSignals deferred;  // a signal stops it between points, as it does rank 0
    outcome.ranks = solvePointsOnRank(plan, points, {}, request.threads, {}, stopAsked);
    outcome.writer = false;
    return outcome;
  }
  std::optional<StudyResumption> resumed;
  if (!request.resumeDir.empty()) resumed.emplace(request.resumeDir, plan, points);
  if (!request.outDir.empty())
    outcome.dir = request.outDir;
  else if (resumed)
    outcome.dir = resumed->destination();
  else
    outcome.dir = defaultStudyDirectory(request.deckPath);
  const PointRanges todo =
      resumed ? resumed->done().complement(points.size()) : PointRanges::all(points.size());
  StudySummary summary(plan);
  writeDirectoryAtomically(
      outcome.dir,
      [&](const fs::path& temporary) {
        writeFile(temporary / kResumeFile, [&](std::ostream& json) {
          json << studyIdentity(plan, points.size()).dump(2) << "\n";
        });
        std::unique_ptr<PointSolver> pointFiles;
        if (request.pointFiles) pointFiles = std::make_unique<PointSolver>(plan);
        const auto pointDir = [&](long long index) {
          return temporary / "points" / std::to_string(index);
        };
        const fs::path table = temporary / "study.csv";
        PointRanges written;
        writeFile(table, [&](std::ostream& csv) {
          csv << studyCsvHeader(plan) << std::flush;
          TableWriter rows(csv, table, summary, resumed ? &*resumed : nullptr, progress,
                           points.size());
          // A point's own results directory, for a row solved here or stored.
          // A point's own results without charts: drawing them would cost more than the rest.
          const auto writePointFiles = [&](const StudyRow& row) {
            Stopwatch pointClock;
            unlessStopping(pointDir(row.index), [&] {
              OutputChoices choices;
              choices.charts = ChartFormat::none;
              choices.units = outcome.units;
              writeRunOutputs(pointFiles->solveFully(row.parameters), pointDir(row.index),
                              choices);
            });
            outcome.pointFileSeconds += pointClock.lap();
          };
          if (pointFiles)  // a stored point's files come along, or are made when it has none
            rows.onStored = [&](const StudyRow& row) {
              const fs::path from = resumed->pointFiles(row.index);
              std::error_code missing;
              if (fs::exists(from, missing)) {
                fs::create_directories(pointDir(row.index).parent_path());
                fs::copy(from, pointDir(row.index), fs::copy_options::recursive);
              } else if (row.ok()) {
                writePointFiles(row);
              }
            };
          outcome.ranks = solvePointsOnRank(
              plan, points, todo, request.threads,
              [&](const StudyRow& row) {
                Stopwatch rowClock;
                outcome.cost += row.cost;
                rows.solved(row);
                outcome.rowSeconds += rowClock.lap();
                if (pointFiles && row.ok()) writePointFiles(row);
              },
              stopAsked);
          rows.storedBefore();
          written = rows.written();
          outcome.resumed = rows.resumedRows;
        });
        // Stopped: what was computed is kept, and the process ends by the signal after.
        outcome.signal = pendingInterruption();
        if (outcome.signal) acknowledgeInterruption();
        outcome.missing = written.complement(points.size());
        outcome.summary = summary.json();
        outcome.summary["path"] = plan.lean ? "lean" : "full";
        outcome.summary["ranks"] = outcome.ranks.ranks;
        if (outcome.partial()) {
          outcome.summary["partial"] = true;
          outcome.summary["stopped_by"] = signalName(outcome.signal);
          outcome.summary["missing"] = missingJson(outcome.missing);
        } else {
          fs::remove(temporary / kResumeFile);  // complete: nothing to resume
        }
        if (!outcome.ranks.lost.empty()) outcome.summary["lost_ranks"] = outcome.ranks.lost;
        // The worst point in full: charts, VTK, CSV and results.json. Its analyses beyond
        // those the study read may fail; that is said in the summary, the study stands.
        if (auto worst = summary.worstPoint()) {
          Json& entry = outcome.summary["worst_point"];
          try {
            outcome.worstWritten = unlessStopping(temporary / "worst", [&] {
              writeRunOutputs(PointSolver(plan).solveFully(worst->second), temporary / "worst",
                              worstChoices);
            });
            if (outcome.worstWritten)
              entry["directory"] = "worst";
            else
              entry["error"] = "not written: the study was stopped by " +
                               signalName(pendingInterruption());
          } catch (const DeckDiagnostic& e) {
            entry["error"] = e.what();
          }
        }
        if (pendingInterruption()) acknowledgeInterruption();  // late: the rows are all there
        writeFile(temporary / "summary.json",
                  [&](std::ostream& json) { json << outcome.summary.dump(2) << "\n"; });
      },
      kResumableNote);
  if (resumed) outcome.resumeNote = resumed->finish();
  outcome.signal = pendingInterruption();
  outcome.points = summary.points();
  outcome.failed = summary.failed();
  outcome.seconds = clock.lap();
  return outcome;
}

fs::path defaultStudyDirectory(const std::string& deckPath) {
  return fs::path("out") / (fs::path(deckPath).stem().string() + "_study");
}

}  // namespace beamrotor

#include "problems/study/DesignStudyRun.hpp"

#include <fstream>
#include <sstream>

#include "fem/timing/Stopwatch.hpp"
#include "problems/deck/DeckReader.hpp"
#include "problems/deck/structure/FormulationOption.hpp"
#include "problems/output/files/AtomicDirectory.hpp"
#include "problems/output/files/FileWriting.hpp"
#include "problems/output/Output.hpp"
#include "problems/study/DesignPoints.hpp"
#include "problems/study/StudyExecution.hpp"
#include "problems/study/StudyMpi.hpp"
#include "problems/study/StudySummary.hpp"
#include "problems/study/StudyTable.hpp"

namespace beamrotor {

namespace {

namespace fs = std::filesystem;

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

}  // namespace

DesignStudyOutcome runDesignStudy(const DesignStudyRequest& request,
                                  const StudyProgress& progress) {
  Stopwatch clock;
  const StudyPlan plan = readPlan(request);
  const DesignPoints points(plan.spec);
  DesignStudyOutcome outcome;
  if (!isStudyManager()) {  // an MPI rank other than 0: solve what rank 0 hands out
    solvePointsOnRank(plan, points, request.threads, {});
    outcome.writer = false;
    return outcome;
  }
  const fs::path stem = fs::path(request.deckPath).stem();
  outcome.dir = request.outDir.empty() ? fs::path("out") / (stem.string() + "_study")
                                       : fs::path(request.outDir);
  StudySummary summary(plan);
  writeDirectoryAtomically(outcome.dir, [&](const fs::path& temporary) {
    std::unique_ptr<PointSolver> pointFiles;
    if (request.pointFiles) pointFiles = std::make_unique<PointSolver>(plan);
    const fs::path table = temporary / "study.csv";
    writeFile(table, [&](std::ostream& csv) {
      csv << studyCsvHeader(plan);
      long long done = 0;
      solvePointsOnRank(plan, points, request.threads, [&](const StudyRow& row) {
        Stopwatch rowClock;
        outcome.cost += row.cost;
        csv << studyCsvRow(row);
        if (!csv) throw std::runtime_error(writeFailure(table, errno));
        summary.add(row);
        outcome.rowSeconds += rowClock.lap();
        if (pointFiles && row.ok()) {
          // A point's own results without charts: drawing them would cost more than the rest.
          Stopwatch pointClock;
          writeRunOutputs(pointFiles->solveFully(row.parameters),
                          temporary / "points" / std::to_string(row.index),
                          OutputChoices{ChartFormat::none, false});
          outcome.pointFileSeconds += pointClock.lap();
        }
        if (progress) progress(++done, points.size());
      });
    });
    outcome.summary = summary.json();
    outcome.summary["path"] = plan.lean ? "lean" : "full";
    // The worst point in full: charts, VTK, CSV and results.json. Its analyses beyond those
    // the study read may fail; that is said in the summary, the study stands.
    if (auto worst = summary.worstPoint()) {
      try {
        writeRunOutputs(PointSolver(plan).solveFully(worst->second), temporary / "worst");
        outcome.summary["worst_point"]["directory"] = "worst";
      } catch (const DeckDiagnostic& e) {
        outcome.summary["worst_point"]["error"] = e.what();
      }
    }
    writeFile(temporary / "summary.json",
              [&](std::ostream& json) { json << outcome.summary.dump(2) << "\n"; });
  });
  outcome.points = summary.points();
  outcome.failed = summary.failed();
  outcome.seconds = clock.lap();
  return outcome;
}

}  // namespace beamrotor

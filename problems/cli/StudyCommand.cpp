// `beamrotor study`: runs a design study (problems/study/DesignStudyRun.hpp) and prints its
// summary: per output the range, mean and spread, per check the pass rate, the exceedance
// probabilities of a sampled study, the worst point, the time and points per second; for a
// study that was stopped, the points missing and how to continue it. Exit 1 when no point
// succeeded; a stopped study ends by its signal (main).
#include <cstdio>
#include <filesystem>
#include <memory>
#include <sstream>

#include "problems/cli/Commands.hpp"
#include "problems/cli/ExitCodes.hpp"
#include "problems/cli/Guarded.hpp"
#include "problems/cli/Progress.hpp"
#include "problems/study/DesignStudyRun.hpp"
#include "problems/study/StudyMpi.hpp"
#include "problems/study/StudyResume.hpp"

namespace beamrotor::cli {

namespace {

std::string formatFigure(double value) {
  char text[32];
  std::snprintf(text, sizeof text, "%.6g", value);
  return text;
}

std::string probabilityText(const Json& p) {
  char text[96];
  std::snprintf(text, sizeof text, "%.4g (95 %% Wilson %.4g .. %.4g)",
                p["probability"].get<double>(), p["wilson95"][0].get<double>(),
                p["wilson95"][1].get<double>());
  return text;
}

/// How the numbers of a summary.json entry (in its `unit`, the column's) are shown: in the
/// user's unit of their quantity where set, else in the column's own.
OutputUnits::Shown shownUnit(const OutputUnits& units, const Json& entry) {
  const std::string unit = entry.value("unit", "");
  return units.valueIn(unit, {1, unit});
}

/// "150 mm": a figure in its column's unit shown as `shown` says, its unit named.
std::string figureText(const Json& value, const OutputUnits::Shown& shown) {
  std::string text = formatFigure(value.get<double>() * shown.factor);
  if (!shown.unit.empty()) {
    text += ' ';
    text += shown.unit;
  }
  return text;
}

/// " D = 150 mm, L = 1.2 m": a point's parameters, each in its shown unit.
std::string parametersText(const Json& parameters, const Json& declared,
                           const OutputUnits& units) {
  std::string text;
  for (const auto& [name, value] : parameters.items()) {
    OutputUnits::Shown shown;
    for (const Json& p : declared)
      if (p["name"] == name) shown = shownUnit(units, p);
    text += text.empty() ? " " : ", ";
    text += name;
    text += " = ";
    text += figureText(value, shown);
  }
  return text;
}

void printStudySummary(std::ostream& out, const DesignStudyOutcome& o) {
  const Json& s = o.summary;
  out << "study " << s["deck"].get<std::string>() << ": ";
  if (o.partial()) out << s["points"] << " of " << s["points"].get<long long>() + o.missing.size();
  else out << s["points"];
  out << " points (" << s["sampling"].get<std::string>() << "), " << s["failed"] << " failed";
  if (o.partial()) out << "; stopped by " << s["stopped_by"].get<std::string>();
  out << "\n";
  out << "  ranks: " << o.ranks.ranks
      << (o.ranks.ranks > 1 ? " (MPI; one point at a time per rank)"
                            : ", threads: " + std::to_string(o.threads))
      << "\n";
  if (o.resumed > 0)
    out << "  resumed: " << o.resumed << " rows from the study resumed, "
        << o.points - o.resumed << " solved now\n";
  out << "  path: "
      << (s["path"].get<std::string>() == "lean"
              ? "lean (the deck parsed once; each point re-evaluates its expressions from byte "
                "code)"
              : "full (the deck read in full at every point)")
      << "\n";
  // Values in the output units chosen (summary.json holds them in the columns' units).
  const OutputUnits& units = o.units;
  for (const Json& output : s["outputs"]) {
    out << "  " << output["name"].get<std::string>() << ":";
    if (!output.contains("mean")) {
      out << " no values\n";
      continue;
    }
    const OutputUnits::Shown shown = shownUnit(units, output);
    out << " min " << figureText(output["min"], shown) << ", mean "
        << figureText(output["mean"], shown) << ", max " << figureText(output["max"], shown)
        << ", sd " << figureText(output["sd"], shown);
    if (output.contains("limit"))
      out << (output.value("limit_is", "upper") == "lower" ? "; below " : "; above ")
          << figureText(output["limit"], shown) << ": " << output["exceeded"]
          << (output.contains("exceedance")
                  ? ", probability " + probabilityText(output["exceedance"])
                  : std::string{});
    out << "\n";
  }
  for (const Json& check : s["checks"]) {
    out << "  check " << check["name"].get<std::string>() << ": " << check["passed"] << " of "
        << check["applicable"] << " passed";
    if (check.contains("failure"))
      out << ", failure probability " << probabilityText(check["failure"]);
    out << "\n";
  }
  if (s.contains("worst_point"))
    out << "  worst point " << s["worst_point"]["point"] << ":"
        << parametersText(s["worst_point"]["parameters"], s["parameters"], units) << "\n";
  for (const Json& failure : s["failures"])
    out << "  point " << failure["point"] << " ("
        << parametersText(failure["parameters"], s["parameters"], units).substr(1)
        << ") failed: " << failure["status"].get<std::string>() << "\n";
  char line[256];
  const long long solvedHere = o.points - o.resumed;
  std::snprintf(line, sizeof line, "time: %.3f s, %.0f points/s\n", o.seconds,
                o.seconds > 0 ? double(solvedHere) / o.seconds : 0.0);
  out << line;
  if (solvedHere <= 0) return;
  // Per point, on the core that solved it (microseconds).
  const double us = 1e6 / double(solvedHere);
  const PointCost& c = o.cost;
  std::snprintf(line, sizeof line,
                "per point (us): read deck %.1f, model %.1f, assemble %.1f, factorise %.1f, "
                "solve and recover %.1f, checks and outputs %.1f, table row %.1f\n",
                c.read * us, c.model * us, c.assembly * us, c.factor * us, c.solve * us,
                c.measure * us, o.rowSeconds * us);
  out << line;
  if (o.pointFileSeconds > 0) {
    std::snprintf(line, sizeof line,
                  "point files: %.1f us per point (solved in full and written), %.0f points/s\n",
                  o.pointFileSeconds * us, double(o.points) / o.pointFileSeconds);
    out << line;
  }
}

/// A study into a directory holding a partial study replaces it: said first, with the way
/// to continue it instead.
void warnBeforeReplacingPartial(const DesignStudyRequest& request, std::ostream& err) {
  if (!request.resumeDir.empty()) return;
  const std::filesystem::path dir = request.outDir.empty()
                                        ? defaultStudyDirectory(request.deckPath)
                                        : std::filesystem::path(request.outDir);
  std::error_code ec;
  if (std::filesystem::exists(dir / kResumeFile, ec))
    err << "beamrotor study: warning: replacing the partial study in " << dir.string()
        << " when this one is written; --resume " << dir.string() << " would continue it\n";
}

/// The results directory's contents, as the console names them.
std::string contentsText(const DesignStudyOutcome& o) {
  std::string text = "study.csv, summary.json";
  if (o.worstWritten) text += ", worst/";
  if (o.partial()) {
    text += ", ";
    text += kResumeFile;
  }
  return text;
}

/// The `beamrotor study` line that continues a stopped study in `dir`.
void printHowToResume(std::ostream& out, const DesignStudyOutcome& o) {
  out << "stopped by " << o.summary["stopped_by"].get<std::string>() << ": " << o.points
      << " rows kept, " << o.missing.size() << " points missing (" << o.missing.text()
      << "); continue with the same command and --resume " << o.dir.string() << "\n";
}

}  // namespace

int studyCommand(const DesignStudyRequest& request, std::ostream& out, std::ostream& err) {
  const MpiSession mpi;
  const bool speaks = isStudyManager();  // other MPI ranks say nothing
  std::ostringstream discard;
  std::ostream& errors = speaks ? err : discard;
  return guarded(errors, [&] {
    std::unique_ptr<ProgressBar> shown;
    DesignStudyOutcome outcome;
    warnBeforeReplacingPartial(request, errors);
    try {
      outcome = runDesignStudy(request, [&](long long done, long long total) {
        if (!shown) shown = std::make_unique<ProgressBar>(errors, ProgressBar::wanted(int(total)));
        if (done % 64 == 0 || done == total) shown->update(int(done), int(total));
      });
    } catch (const DeckDiagnostic&) {
      throw;
    } catch (const std::runtime_error& e) {
      errors << "beamrotor study: cannot write the results: " << e.what() << "\n";
      return int(kSolveFailure);
    }
    shown.reset();
    if (!outcome.writer) return int(kOk);
    printStudySummary(out, outcome);
    out << "results: " << outcome.dir.string() << "/ (" << contentsText(outcome) << ")\n";
    if (!outcome.resumeNote.empty()) out << outcome.resumeNote << "\n";
    for (const std::string& lost : outcome.ranks.lost)
      errors << "beamrotor study: lost " << lost << "; its unfinished points are missing\n";
    if (outcome.partial()) printHowToResume(errors, outcome);
    if (outcome.points > 0 && outcome.failed == outcome.points) {
      errors << "beamrotor study: no point succeeded (" << outcome.failed
             << " failed; summary.json lists them)\n";
      return int(kSolveFailure);
    }
    return int(kOk);
  });
}

}  // namespace beamrotor::cli

// `beamrotor study`: runs a design study (problems/study/DesignStudyRun.hpp) and prints its
// summary: per output the range, mean and spread, per check the pass rate, the exceedance
// probabilities of a sampled study, the worst point, the time and points per second.
#include <cstdio>
#include <memory>
#include <sstream>

#include "problems/cli/Commands.hpp"
#include "problems/cli/ExitCodes.hpp"
#include "problems/cli/Guarded.hpp"
#include "problems/cli/Progress.hpp"
#include "problems/study/StudyMpi.hpp"

namespace beamrotor::cli {

namespace {

std::string formatFigure(const Json& value) {
  char text[32];
  std::snprintf(text, sizeof text, "%.6g", value.get<double>());
  return text;
}

std::string probabilityText(const Json& p) {
  char text[96];
  std::snprintf(text, sizeof text, "%.4g (95 %% Wilson %.4g .. %.4g)",
                p["probability"].get<double>(), p["wilson95"][0].get<double>(),
                p["wilson95"][1].get<double>());
  return text;
}

void printStudySummary(std::ostream& out, const DesignStudyOutcome& o) {
  const Json& s = o.summary;
  out << "study " << s["deck"].get<std::string>() << ": " << s["points"] << " points ("
      << s["sampling"].get<std::string>() << "), " << s["failed"] << " failed\n";
  out << "  path: "
      << (s["path"].get<std::string>() == "lean"
              ? "lean (the deck parsed once; each point re-evaluates its expressions from byte "
                "code)"
              : "full (the deck read in full at every point)")
      << "\n";
  for (const Json& output : s["outputs"]) {
    out << "  " << output["name"].get<std::string>() << ":";
    if (!output.contains("mean")) {
      out << " no values\n";
      continue;
    }
    out << " min " << formatFigure(output["min"]) << ", mean " << formatFigure(output["mean"])
        << ", max " << formatFigure(output["max"]) << ", sd " << formatFigure(output["sd"]);
    if (output.contains("limit"))
      out << "; above " << formatFigure(output["limit"]) << ": " << output["exceeded"]
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
  if (s.contains("worst_point")) {
    out << "  worst point " << s["worst_point"]["point"] << ":";
    for (const auto& [name, value] : s["worst_point"]["parameters"].items())
      out << " " << name << " = " << formatFigure(value);
    out << "\n";
  }
  for (const Json& failure : s["failures"])
    out << "  point " << failure["point"] << " failed: " << failure["status"].get<std::string>()
        << "\n";
  char line[256];
  std::snprintf(line, sizeof line, "time: %.3f s, %.0f points/s\n", o.seconds,
                o.seconds > 0 ? double(o.points) / o.seconds : 0.0);
  out << line;
  if (o.points == 0) return;
  // Per point, on the core that solved it (microseconds).
  const double us = 1e6 / double(o.points);
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

}  // namespace

int studyCommand(const DesignStudyRequest& request, std::ostream& out, std::ostream& err) {
  const MpiSession mpi;
  const bool speaks = isStudyManager();  // other MPI ranks say nothing
  std::ostringstream discard;
  std::ostream& errors = speaks ? err : discard;
  return guarded(errors, [&] {
    std::unique_ptr<ProgressBar> shown;
    DesignStudyOutcome outcome;
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
    out << "results: " << outcome.dir.string() << "/ (study.csv, summary.json, worst/)\n";
    return int(kOk);
  });
}

}  // namespace beamrotor::cli

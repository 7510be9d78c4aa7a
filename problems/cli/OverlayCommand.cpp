// `beamrotor overlay`: solves several decks (each without its sweep) and draws their static
// diagrams on one chart, one line per deck.
#include <set>

#include "problems/cli/Commands.hpp"
#include "problems/cli/ExitCodes.hpp"
#include "problems/cli/Guarded.hpp"
#include "problems/output/files/AtomicDirectory.hpp"
#include "problems/output/OverlayOutput.hpp"

namespace beamrotor::cli {

int overlayCommand(const OverlayRequest& request, std::ostream& out, std::ostream& err) {
  return guarded(err, [&] {
    // 1. Solve every deck before writing anything.
    std::vector<Study> studies;
    std::set<std::string> labels;
    for (const std::string& path : request.deckPaths) {
      StudyRequest one;
      one.deckPath = path;
      one.sets = request.sets;
      one.noSweep = true;
      studies.push_back(solveStudy(one));
      const RunResult& run = *studies.back().run;
      if (!overlaidAnalysis(run))
        throw DeckError(path, DeckPlace{0, 0, "analyses"},
                        "has no static analysis along a line to overlay (a frame's members or "
                        "a model without beams have no diagrams along one line)");
      if (!labels.insert(run.deckName).second)
        throw DeckError(path, DeckPlace{0, 0, "overlay"},
                        "is given twice; for several values of one deck's parameter use "
                        "`beamrotor solve DECK --sweep NAME=V1,V2`");
    }
    std::vector<Diagram> shown;
    for (Diagram d : kAllDiagrams)
      if (request.quantity == "all" || request.quantity == diagramName(d)) shown.push_back(d);

    // 2. Write the tables and the chart.
    const std::filesystem::path dir =
        request.outDir.empty() ? std::filesystem::path("out") / "overlay"
                               : std::filesystem::path(request.outDir);
    const OutputUnits units = studies.front().deck.output.units.overlaid(request.units);
    std::vector<OverlaidRun> runs;
    for (const Study& s : studies) runs.push_back({s.run->deckName, &*s.run});
    bool drawn = false;
    try {
      writeDirectoryAtomically(dir, [&](const std::filesystem::path& temporary) {
        drawn = writeOverlay(temporary, runs, shown, units);
      });
    } catch (const std::exception& e) {
      err << dir.string() << ": cannot write the results: " << e.what() << "\n";
      return int(kSolveFailure);
    }
    for (const OverlaidRun& r : runs)
      out << r.label << ": " << overlaidAnalysis(*r.run)->name << " -> " << r.label
          << "_fields.csv\n";
    out << (drawn ? "chart: " + (dir / "overlay.svg").string() + " (and .png)"
                  : std::string("no chart: gnuplot is not installed"))
        << "\nresults: " << dir.string() << "/\n";
    return int(kOk);
  });
}

}  // namespace beamrotor::cli

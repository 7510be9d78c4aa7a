// `beamrotor overlay`: solves several decks (each without its sweep) and draws their static
// diagrams on one chart, one line per deck.
#include "problems/cli/Commands.hpp"
#include "problems/cli/ExitCodes.hpp"
#include "problems/cli/Guarded.hpp"
#include "problems/output/files/AtomicDirectory.hpp"
#include "problems/output/OverlayOutput.hpp"

namespace beamrotor::cli {

int overlayCommand(const OverlayRequest& request, std::ostream& out, std::ostream& err) {
  return guarded(err, [&] {
    // 1. Solve every deck before writing anything.
    const std::vector<Study> studies = solveOverlaid(request.deckPaths, request.sets);
    const std::vector<Diagram> shown = overlaidDiagrams(request.quantity);

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

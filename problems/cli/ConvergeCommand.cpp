// `beamrotor converge`: reads the deck, runs the convergence study, writes its files and prints
// one line per method and level.
#include <cstdio>

#include "problems/cli/Commands.hpp"
#include "problems/cli/ExitCodes.hpp"
#include "problems/cli/Guarded.hpp"
#include "problems/converge/ConvergeOutput.hpp"
#include "problems/deck/DeckReader.hpp"
#include "problems/deck/ShownFieldUnit.hpp"

namespace beamrotor::cli {

namespace {

void printStudy(std::ostream& out, const ConvergeStudy& s, const OutputUnits& units) {
  // Values and references in the user's unit of the quantity where set, else its own.
  const OutputUnits::Shown shown = shownField(units, s.unit);
  const std::string unit = shown.unit.empty() ? "" : " " + shown.unit;
  out << "converge " << s.deckPath << ": " << s.quantity << " (analysis " << s.analysis << "; "
      << s.choice << "), refining the " << s.refinement << ", reference: "
      << (s.check.empty() ? "Richardson-extrapolated per method (estimate)"
                          : "closed form of check '" + s.check + "'")
      << "\n";
  for (const ConvergeSeries& series : s.series) {
    char line[200];
    std::snprintf(line, sizeof line, "%s (reference %.10g%s)\n", series.method.label.c_str(),
                  series.reference * shown.factor, unit.c_str());
    out << line;
    for (const ConvergeLevel& l : series.levels) {
      if (l.steps > 0)
        std::snprintf(line, sizeof line,
                      "  level %d: %8d steps %7d dofs  %.6e s  value %.12g%s  error %.3e",
                      l.level, l.steps, l.dofs, l.total, l.value * shown.factor, unit.c_str(),
                      l.error);
      else
        std::snprintf(line, sizeof line,
                      "  level %d: %6d elements %7d dofs  %.6e s  value %.12g%s  error %.3e",
                      l.level, l.elements, l.dofs, l.total, l.value * shown.factor, unit.c_str(),
                      l.error);
      out << line;
      if (l.order) {
        std::snprintf(line, sizeof line, "  order %.2f", *l.order);
        out << line;
      }
      out << "\n";
    }
    if (!series.failure.empty()) out << "  stopped at " << series.failure << "\n";
  }
}

}  // namespace

int convergeCommand(const ConvergeRequest& request, std::ostream& out, std::ostream& err) {
  return guarded(err, [&] {
    const DeckSource source = loadDeckFile(request.deckPath);
    std::vector<ParameterOverride> overrides;
    for (const std::string& s : request.sets) overrides.push_back(parseOverride(s, source.path));
    const Deck deck = readDeck(source, overrides);
    const OutputUnits units = deck.output.units.overlaid(request.units);
    const ConvergeStudy study = runConvergence(deck, request.options);
    const std::filesystem::path dir =
        request.outDir.empty() ? std::filesystem::path("out") / (source.stem + "_converge")
                               : std::filesystem::path(request.outDir);
    printStudy(out, study, units);
    try {
      writeConvergenceOutputs(study, dir, units);
    } catch (const std::exception& e) {
      err << dir.string() << ": cannot write the results: " << e.what() << "\n";
      return int(kSolveFailure);
    }
    out << "results: " << dir.string() << "/\n";
    return int(kOk);
  });
}

}  // namespace beamrotor::cli

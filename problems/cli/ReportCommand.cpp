#include "problems/cli/ReportCommand.hpp"

#include "problems/cli/ExitCodes.hpp"
#include "problems/converge/ConvergeOutput.hpp"
#include "problems/converge/ConvergeStudy.hpp"
#include "problems/deck/DeckReader.hpp"
#include "problems/deck/parse/DeckError.hpp"
#include "problems/verify/DeckChecks.hpp"

namespace beamrotor::cli {

namespace {

namespace fs = std::filesystem;

/// Each deck's convergence study into DIR/convergence/<deck>/, as `beamrotor converge` writes
/// it; the decks with nothing to converge are noted in options.notConverged instead.
void convergeDecks(verify::ReportOptions& options, std::ostream& log) {
  for (const fs::path& file : verify::decksIn(options.problemsDir)) {
    const Deck deck = readDeck(loadDeckFile(file));
    if (const auto why = nothingToConverge(deck)) {
      log << "  " << file.filename().string() << ": skipped, " << *why << "\n";
      options.notConverged.emplace_back(file.filename().string(), *why);
      continue;
    }
    log << "  " << file.filename().string() << ": convergence study\n";
    writeConvergenceOutputs(runConvergence(deck, ConvergeOptions{}),
                            options.outDir / "convergence" / deck.stem);
  }
}

}  // namespace

int reportCommand(const ReportRequest& request, std::ostream& out, std::ostream& err) {
  try {
    verify::ReportOptions options = request.report;
    if (request.converge) {
      err << "convergence studies of the decks in " << options.problemsDir.string() << "\n";
      convergeDecks(options, err);
    }
    const verify::ReportSummary s = verify::writeReport(options, err);
    out << "checks: " << s.checks - s.failedChecks << " pass, " << s.failedChecks << " fail, "
        << s.notApplied << " did not apply";
    if (s.unsolvedDecks) out << ", " << s.unsolvedDecks << " deck(s) not solved";
    if (!options.notConverged.empty())
      out << "; " << options.notConverged.size() << " deck(s) with nothing to converge";
    out << "\nreport: " << s.page.string() << "\n";
    return kOk;
  } catch (const DeckError& e) {
    err << e.what() << "\n";
    return kInputError;
  } catch (const std::invalid_argument& e) {
    err << "beamrotor report: " << e.what() << "\n";
    return kInputError;
  } catch (const std::exception& e) {
    err << "beamrotor report: " << e.what() << "\n";
    return kSolveFailure;
  }
}

}  // namespace beamrotor::cli

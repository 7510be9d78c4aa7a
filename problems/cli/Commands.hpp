// The subcommands of the beamrotor command line, callable without CLI11 (tests call them
// directly): each reads a deck, solves it and reports, returning the process exit code.
#pragma once

#include <optional>
#include <ostream>
#include <string>
#include <vector>

#include "problems/bench/Bench.hpp"
#include "problems/converge/ConvergeStudy.hpp"
#include "problems/deck/OutputChoices.hpp"
#include "problems/run/Study.hpp"
#include "problems/study/DesignStudyRun.hpp"

namespace beamrotor::cli {

struct SolveOptions {
  StudyRequest study;
  std::string outDir;  ///< empty: out/<deck stem>
  /// Set: also export the free-free matrices there (empty: <outDir>/matrices).
  std::optional<std::string> exportMatrices;
  /// `--charts`, `--point-files`, `--units`: over the deck's `output:` choices.
  DeckOutput output;
};

/// `beamrotor solve`: solve, write results.json, CSV, VTK and charts, print a summary.
int solveCommand(const SolveOptions& options, std::ostream& out, std::ostream& err);

/// `beamrotor check`: solve and print the checks; kChecksFailed when any fails. Values are
/// shown in `units` (`--units`) over the deck's `output: units:`.
int checkCommand(const StudyRequest& request, std::ostream& out, std::ostream& err,
                 const OutputUnits& units = {});

/// `beamrotor bench`: prints the benchmark table; writes its JSON to jsonPath when given.
/// A size the kind cannot build is one line on err and kInputError.
int benchCommand(const BenchOptions& options, const std::string& jsonPath, std::ostream& out,
                 std::ostream& err);

/// What `beamrotor converge` reads and where it writes.
struct ConvergeRequest {
  std::string deckPath;
  std::vector<std::string> sets;  ///< "NAME=VALUE" overrides, as typed
  ConvergeOptions options;
  std::string outDir;  ///< empty: out/<deck stem>_converge
  OutputUnits units;   ///< `--units`, over the deck's `output: units:`
};

/// `beamrotor converge` (ConvergeCommand.cpp): the convergence study of one deck quantity,
/// written as convergence.json, convergence.csv and two log-log charts.
int convergeCommand(const ConvergeRequest& request, std::ostream& out, std::ostream& err);

/// What `beamrotor overlay` reads and where it writes.
struct OverlayRequest {
  std::vector<std::string> deckPaths;  ///< two or more decks, each solved without its sweep
  std::vector<std::string> sets;       ///< "NAME=VALUE" overrides, applied to every deck
  std::string quantity = "all";        ///< a diagramName or "all"
  std::string outDir;                  ///< empty: out/overlay
  OutputUnits units;  ///< `--units`, over the first deck's `output: units:`
};

/// `beamrotor overlay` (OverlayCommand.cpp): the static diagrams of several decks on one chart.
int overlayCommand(const OverlayRequest& request, std::ostream& out, std::ostream& err);

/// `beamrotor study` (StudyCommand.cpp): a design study written as study.csv, summary.json
/// and the worst point's results; under mpirun only rank 0 prints and writes.
int studyCommand(const DesignStudyRequest& request, std::ostream& out, std::ostream& err);

}  // namespace beamrotor::cli

#include "problems/cli/App.hpp"

#include <CLI/CLI.hpp>
#include <algorithm>
#include <cstdlib>
#include <filesystem>
#include <new>
#include <string>
#include <vector>

#include "problems/cli/Commands.hpp"
#include "problems/cli/ExitCodes.hpp"
#include "problems/cli/ReportCommand.hpp"
#include "problems/cli/WholeNumberOption.hpp"
#include "problems/deck/structure/Formulations.hpp"
#include "problems/deck/parse/Suggest.hpp"
#include "problems/run/DeckRunner.hpp"
#include "problems/study/StudyMpi.hpp"

namespace beamrotor::cli {

namespace {

/// Where the worked examples are, for --help: the installed ones beside this executable
/// (PREFIX/share/beamrotor/examples for PREFIX/bin/beamrotor), else the source tree's when
/// run from a build directory in it. $BEAMROTOR_EXAMPLES_PLACE, when set, is said instead:
/// the manual page is made by the build tree's executable, for the installed one.
std::string examplesPlace() {
  namespace fs = std::filesystem;
  if (const char* place = std::getenv("BEAMROTOR_EXAMPLES_PLACE"); place && *place) return place;
  std::error_code ec;
  const fs::path bin = fs::read_symlink("/proc/self/exe", ec).parent_path();
  if (!ec) {
    const fs::path installed = bin.parent_path() / "share" / "beamrotor" / "examples";
    if (fs::is_directory(installed, ec)) return fs::weakly_canonical(installed, ec).string();
    if (fs::is_directory(bin.parent_path() / "problems", ec) &&
        fs::exists(bin.parent_path() / "problems" / "deck" / "FORMAT.md", ec))
      return "problems/ of the source tree";
  }
  return "share/beamrotor/examples/ of the installation";
}

std::string description() {
  // Appended piece by piece: GCC 12 warns (-Wrestrict, wrongly) on "literal" + a temporary.
  std::string text = "beamrotor: finite-element beams, frames and rotors.\n";
  text += "Solves the engineering scenes described by YAML decks; worked examples, each with "
          "its reference solution: ";
  text += examplesPlace();
  text += ".\nExit codes: 0 ok, 1 an analysis failed (study: no point succeeded), 2 bad input, 3 a "
          "check failed (check); stopped by SIGINT or SIGTERM: ended by the signal (130, 143).";
  return text;
}

/// The options every deck-reading subcommand shares.
void addDeckOptions(CLI::App& sub, StudyRequest& request) {
  sub.add_option("deck", request.deckPath, "the deck to solve, e.g. problems/pump_rod.yaml")
      ->required();
  sub.add_option("--set", request.sets,
                 "override a deck parameter (repeatable), e.g. --set eta=0.2; the value may be "
                 "an expression of constants")
      ->type_name("NAME=VALUE")
      ->allow_extra_args(false);
  sub.add_option("--sweep", request.sweep,
                 "solve once per value of a parameter, replacing the deck's own sweep: "
                 "NAME=FROM:TO:STEPS (STEPS intervals) or NAME=V1,V2,...")
      ->type_name("SPEC");
  sub.add_option("--formulation", request.formulation,
                 "beam theory for every segment, replacing the deck's: " +
                     joinNames(formulationNames()))
      ->type_name("THEORY");
  sub.add_flag("--no-sweep", request.noSweep,
               "solve the parameters' own values once even if the deck has a sweep");
}

/// `--units Q=UNIT,...` on `sub`, checked as it is parsed (what is wrong with it, as an input
/// error), `what` saying what it sets.
void addUnitsOption(CLI::App& sub, std::string& units, const std::string& what) {
  sub.add_option("--units", units, what + ". Quantities: " + joinNames(outputQuantityNames()))
      ->check([](const std::string& list) -> std::string {
        try {
          parseOutputUnits(list);
          return "";
        } catch (const std::invalid_argument& e) {
          return e.what();
        }
      })
      ->type_name("Q=UNIT,...");
}

/// A first argument that is neither an option nor a subcommand (`beamrotor slove deck.yaml`):
/// one line naming it, the closest subcommand and the list; empty when the argument is fine.
std::string unknownCommand(const CLI::App& app, int argc, const char* const* argv) {
  if (argc < 2 || argv[1][0] == '-' || argv[1][0] == '\0') return {};
  std::vector<std::string> names;
  for (const CLI::App* sub : app.get_subcommands([](const CLI::App*) { return true; }))
    names.push_back(sub->get_name());
  const std::string word = argv[1];
  if (std::find(names.begin(), names.end(), word) != names.end()) return {};
  const std::string best = closestMatch(word, names, 2);  // six commands, far apart
  return "beamrotor: '" + word + "' is not a command" +
         (best.empty() ? std::string{} : "; did you mean " + best + "?") +
         " (commands: " + joinNames(names) + "; beamrotor --help)";
}

}  // namespace

int runCommandLine(int argc, const char* const* argv, std::ostream& out, std::ostream& err) {
  CLI::App app{description(), "beamrotor"};
  app.set_version_flag("--version", std::string("beamrotor ") + BEAMROTOR_VERSION);
  app.require_subcommand(1);

  SolveOptions solve;
  CLI::App* solveCmd = app.add_subcommand(
      "solve",
      "Solve every analysis of a deck, write results.json, CSV, VTK and charts, and "
      "print a summary with the deck's checks.");
  addDeckOptions(*solveCmd, solve.study);
  solveCmd
      ->add_option("--out,-o", solve.outDir,
                   "output directory (default: out/<deck name>/); replaced as a whole")
      ->type_name("DIR");
  solveCmd
      ->add_option("--export-matrices", solve.exportMatrices,
                   "also write K, M and f (Matrix Market) and dofs.csv into DIR "
                   "(default: <out>/matrices)")
      ->expected(0, 1)
      ->type_name("[DIR]");
  std::string charts;
  solveCmd
      ->add_option("--charts", charts,
                   "chart images: png (default), svg, both or none; replaces the deck's "
                   "output: charts")
      ->check(CLI::IsMember(chartFormatNames()))
      ->type_name("FORMAT");
  bool fullTables = false;
  CLI::Option* fullTablesFlag = solveCmd->add_flag(
      "--full-tables", fullTables,
      "a long line's fields table at every station (5 an element), not thinned to "
      "about 4000 stations");
  std::string units;
  addUnitsOption(*solveCmd, units,
                 "units of the summary, CSV tables and charts, e.g. length=mm,force=kN,"
                 "stress=MPa,speed=rpm; over the deck's output: units (results.json stays SI)");
  bool allCases = false;
  CLI::Option* allCasesFlag = solveCmd->add_flag(
      "--all-cases", allCases,
      "statics with load combinations: a VTK file for every load case and combination, not "
      "only for the combinations that govern an extreme");
  bool pointFiles = false;
  CLI::Option* pointFilesFlag = solveCmd->add_flag(
      "--point-files", pointFiles,
      "a sweep: also every value's own results directory (value_000/, ...) and a ParaView "
      "series over them");

  StudyRequest check;
  CLI::App* checkCmd = app.add_subcommand(
      "check", "Solve a deck and compare it with its closed forms; exits 3 if any check fails.");
  addDeckOptions(*checkCmd, check);
  std::string checkUnits;
  addUnitsOption(*checkCmd, checkUnits,
                 "units of the checks' values, e.g. length=mm,speed=rpm; over the deck's "
                 "output: units");

  BenchOptions bench;
  std::string benchJsonPath;
  CLI::App* benchCmd =
      app.add_subcommand("bench",
                         "Time a standard model (medians of repeated runs) and report its accuracy "
                         "against the exact reference.");
  benchCmd->add_option("--kind", bench.kind, "standard model: planar, grid3d, rotor or frame3d")
      ->check(CLI::IsMember({"planar", "grid3d", "rotor", "frame3d"}));
  CLI::Option* elements =
      benchCmd
          ->add_option("--elements", bench.elements,
                       "element count (planar: whole spans of 10; grid3d: nearest grillage; "
                       "rotor: a multiple of 4)")
          ->check(wholeNumber(4, 100000000));
  benchCmd->add_option("--dofs", bench.dofs, "size the model to the free dof count nearest N")
      ->type_name("N")
      ->check(wholeNumber(1, 1000000000))
      ->excludes(elements);
  benchCmd
      ->add_option("--members", bench.members,
                   "frame3d: the member count to come nearest (a building of n x n bays and n "
                   "storeys)")
      ->check(CLI::Range(1, 10000000))
      ->excludes(elements);
  benchCmd
      ->add_option("--combinations", bench.combinations,
                   "frame3d: load combinations of its three load cases (default 0)")
      ->check(CLI::Range(0, 100000));
  benchCmd
      ->add_option("--modes", bench.modes,
                   "lowest modes, rotor: Campbell lines (default 10, rotor 12; 0: statics only)")
      ->check(wholeNumber(0, 1000));
  benchCmd->add_option("--repeat", bench.repeat, "runs; times are medians")
      ->check(wholeNumber(1, 1000));
  benchCmd->add_option("--json", benchJsonPath, "also write the figures as JSON")
      ->type_name("FILE");
  benchCmd
      ->add_option("--export", bench.exportDir,
                   "write the model's K, M and load vector (Matrix Market) into DIR")
      ->type_name("DIR");
  benchCmd->add_flag("--cold", bench.cold,
                     "leave the heap unpopulated, as `solve` does: first-touch page faults count "
                     "(make bench times such runs as fresh processes)");

  ReportRequest report;
  CLI::App* reportCmd =
      app.add_subcommand("report",
                         "Regenerate the verification report (one HTML page): every shipped deck's "
                         "checks, convergence charts when present, and the failure-case studies.");
  reportCmd
      ->add_option("--out,-o", report.report.outDir, "output directory (default: out/report/)")
      ->type_name("DIR");
  reportCmd
      ->add_option("--decks", report.report.problemsDir,
                   "directory of the decks to check (default: problems/ of the source "
                   "tree, when run from it)")
      ->type_name("DIR");
  reportCmd->add_flag("--converge", report.converge,
                      "first run each deck's convergence study into DIR/convergence/<deck>/ "
                      "(skipping, and naming on the page, decks with nothing to converge)");

  ConvergeRequest converge;
  CLI::App* convergeCmd =
      app.add_subcommand("converge",
                         "Refine the deck's mesh level by level (halving every element) with each "
                         "element formulation; write convergence.json and error-against-dofs and "
                         "error-against-time charts.");
  convergeCmd->add_option("deck", converge.deckPath, "the deck")->required();
  convergeCmd->add_option("--set", converge.sets, "override a deck parameter (repeatable)")
      ->type_name("NAME=VALUE")
      ->allow_extra_args(false);
  convergeCmd
      ->add_option("--quantity", converge.options.quantity,
                   "a deck quantity, e.g. 'frequency 1' (default: the first check's)")
      ->type_name("Q");
  convergeCmd
      ->add_option("--levels", converge.options.levels,
                   "meshes: the deck's own and N-1 refinements (default 5)")
      ->type_name("N")
      ->check(wholeNumber(1, 16));
  convergeCmd
      ->add_option("--out,-o", converge.outDir,
                   "output directory (default: out/<deck name>_converge/)")
      ->type_name("DIR");
  std::string convergeUnits;
  addUnitsOption(*convergeCmd, convergeUnits,
                 "units of the printed values, the tables' value column and the time axis, "
                 "e.g. length=mm; over the deck's output: units");

  OverlayRequest overlay;
  CLI::App* overlayCmd = app.add_subcommand(
      "overlay",
      "Solve several decks (each without its sweep) and draw their static diagrams on one "
      "chart, one line per deck; write each deck's fields CSV beside it.");
  overlayCmd->add_option("decks", overlay.deckPaths, "two or more decks")
      ->required()
      ->expected(2, 100);
  overlayCmd
      ->add_option("--set", overlay.sets, "override a parameter of every deck (repeatable)")
      ->type_name("NAME=VALUE")
      ->allow_extra_args(false);
  overlayCmd
      ->add_option("--quantity", overlay.quantity,
                   "the diagram to draw: deflection, rotation, moment, force (shear force), "
                   "stress, shear (shear stress) or all (default)")
      ->check(CLI::IsMember({"deflection", "rotation", "moment", "force", "stress", "shear",
                             "all"}))
      ->type_name("Q");
  overlayCmd->add_option("--out,-o", overlay.outDir, "output directory (default: out/overlay/)")
      ->type_name("DIR");
  std::string overlayUnits;
  addUnitsOption(*overlayCmd, overlayUnits,
                 "units of the tables and the chart, e.g. length=mm,force=kN; over the first "
                 "deck's output: units");

  DesignStudyRequest study;
  CLI::App* studyCmd = app.add_subcommand(
      "study",
      "Solve a deck at every point of a design study (a grid of --sweep values, or samples "
      "of --sample distributions) and write study.csv (a row per point), summary.json and the "
      "worst point's results.");
  studyCmd->add_option("deck", study.deckPath, "the deck, e.g. problems/pump_rod.yaml")
      ->required();
  studyCmd->add_option("--set", study.sets, "override a deck parameter (repeatable)")
      ->type_name("NAME=VALUE")
      ->allow_extra_args(false);
  studyCmd
      ->add_option("--sweep", study.study.sweeps,
                   "a grid axis (repeatable; several form a grid): NAME=FROM:TO:STEPS or "
                   "NAME=V1,V2,...")
      ->type_name("SPEC")
      ->allow_extra_args(false);
  studyCmd
      ->add_option("--sample", study.study.samples,
                   "a sampled parameter (repeatable): NAME=uniform(LOW,HIGH), "
                   "NAME=normal(MEAN,SD) or NAME=lognormal(MEDIAN,SIGMA), each with optional "
                   ",LOWER,UPPER bounds")
      ->type_name("NAME=DIST(...)")
      ->allow_extra_args(false);
  studyCmd->add_option("--samples", study.study.count, "how many points to sample")
      ->type_name("N")
      ->check(wholeNumber(1, std::uint64_t(kMaxStudyPoints)));
  studyCmd
      ->add_option("--seed", study.study.seed,
                   "seed of the random engine (std::mt19937_64), 0 to 2^64 - 1")
      ->type_name("S")
      ->check(wholeNumber(0, UINT64_MAX));
  studyCmd
      ->add_option("--sampling", study.study.sampling,
                   "random (default when sampling) or latin-hypercube")
      ->type_name("HOW");
  studyCmd
      ->add_option("--output", study.study.outputs,
                   "a quantity to record at every point (repeatable; default: the checks' "
                   "quantities), optionally with an upper limit: 'stress max <= 150 MPa'")
      ->type_name("QUANTITY")
      ->allow_extra_args(false);
  studyCmd->add_option("--threads", study.threads, "threads over points (default 1)")
      ->check(wholeNumber(1, 1024));
  studyCmd->add_flag("--point-files", study.pointFiles,
                     "also write every point's results directory (points/<k>/)");
  studyCmd->add_flag("--full-path", study.fullPath,
                     "read the deck in full at every point instead of the lean path (the "
                     "reference the lean path equals; slower)");
  studyCmd
      ->add_option("--formulation", study.formulation,
                   "beam theory for every segment, replacing the deck's: " +
                       joinNames(formulationNames()))
      ->type_name("THEORY");
  studyCmd
      ->add_option("--out,-o", study.outDir,
                   "output directory (default: out/<deck name>_study/, or where the resumed "
                   "study was going); replaced as a whole")
      ->type_name("DIR");
  std::string studyUnits;
  addUnitsOption(*studyCmd, studyUnits,
                 "units of the printed summary and of the worst point's (and --point-files') "
                 "results, e.g. length=mm,stress=MPa; over the deck's output: units (study.csv "
                 "and summary.json keep the units they name)");
  studyCmd
      ->add_option("--resume", study.resumeDir,
                   "continue the study that was stopped in DIR (its partial results, or the "
                   "DIR.tmp-XXXXXX a killed run left), solving only its missing points; give "
                   "the deck and options it was run with")
      ->type_name("DIR");

  if (const std::string unknown = unknownCommand(app, argc, argv); !unknown.empty()) {
    err << unknown << "\n";
    return kInputError;
  }
  try {
    app.parse(argc, argv);
  } catch (const CLI::ParseError& e) {
    // Help and version are "errors" that succeed; real parse errors are input errors.
    const int code = app.exit(e, out, err);
    return code == 0 ? int(kOk) : int(kInputError);
  }

  // Only `study` shares its work among MPI ranks; any other command under mpirun -n N would
  // run N times over and N processes would write the same results directory.
  if (!studyCmd->parsed() && launchedRanks() > 1) {
    if (launchedRank() == 0)
      err << "beamrotor " << app.get_subcommands().front()->get_name() << ": started by mpirun as "
          << launchedRanks() << " processes, each of which would do the same work and write the "
             "same results; only `beamrotor study` shares its points among MPI ranks (e.g. "
             "`mpirun -n "
          << launchedRanks()
          << " beamrotor study DECK --sweep NAME=FROM:TO:STEPS`). Run this command without "
             "mpirun.\n";
    return kInputError;
  }
  if (!charts.empty()) solve.output.charts = chartFormatNamed(charts);
  if (!units.empty()) solve.output.units = parseOutputUnits(units);
  const OutputUnits checkOutputUnits =
      checkUnits.empty() ? OutputUnits() : parseOutputUnits(checkUnits);
  if (!convergeUnits.empty()) converge.units = parseOutputUnits(convergeUnits);
  if (!overlayUnits.empty()) overlay.units = parseOutputUnits(overlayUnits);
  if (!studyUnits.empty()) study.units = parseOutputUnits(studyUnits);
  if (pointFilesFlag->count() > 0) solve.output.pointFiles = pointFiles;
  if (fullTablesFlag->count() > 0) solve.output.fullTables = fullTables;
  if (allCasesFlag->count() > 0) solve.output.allCases = allCases;
  try {
    if (solveCmd->parsed()) return solveCommand(solve, out, err);
    if (benchCmd->parsed()) return benchCommand(bench, benchJsonPath, out, err);
    if (reportCmd->parsed()) return reportCommand(report, out, err);
    if (convergeCmd->parsed()) return convergeCommand(converge, out, err);
    if (overlayCmd->parsed()) return overlayCommand(overlay, out, err);
    if (studyCmd->parsed()) return studyCommand(study, out, err);
    return checkCommand(check, out, err, checkOutputUnits);
  } catch (const std::bad_alloc&) {
    err << "beamrotor: " << kOutOfMemory << "\n";
    return kSolveFailure;
  } catch (const std::exception& e) {
    err << "beamrotor: internal error: " << e.what() << "\n";
    return kSolveFailure;
  }
}

}  // namespace beamrotor::cli

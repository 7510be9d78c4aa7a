// `beamrotor study`: a deck solved at every point of a design study (DesignStudy.hpp), its
// table streamed to study.csv as the points finish (each row written through to the system
// at once, so it outlives the process), then summary.json and the worst point's full results
// (worst/), all in one results directory replaced atomically at the end
// (problems/output/AtomicDirectory). Per-point results directories (points/<k>/) only when
// asked. Under mpirun the ranks share the points (StudyMpi.hpp) and rank 0 writes.
//
// Asked to stop (SIGINT, SIGTERM, SIGHUP), the study starts no new point, writes the rows it
// has and a summary.json marked partial that names the missing points, and puts them in
// place; the process then ends by the signal. `--resume DIR` continues such a study
// (StudyResume.hpp).
#pragma once

#include <filesystem>
#include <functional>
#include <string>
#include <vector>

#include "problems/deck/OutputUnits.hpp"
#include "problems/deck/study/DesignStudy.hpp"
#include "problems/output/JsonWriter.hpp"
#include "problems/study/PointRanges.hpp"
#include "problems/study/StudyMpi.hpp"
#include "problems/study/StudyPoint.hpp"

namespace beamrotor {

struct DesignStudyRequest {
  std::string deckPath;
  std::vector<std::string> sets;  ///< "NAME=VALUE" overrides, as typed
  std::string formulation;        ///< --formulation, or empty
  StudyCommandLine study;
  std::string outDir;      ///< empty: out/<deck stem>_study, or where --resume's study goes
  std::string resumeDir;   ///< --resume: a partial study to continue, or empty
  int threads = 1;         ///< threads over points on this machine (per MPI rank)
  bool pointFiles = false; ///< also every point's results directory (no charts), points/<k>/
  bool fullPath = false;   ///< read the deck in full at every point (StudyPlan::lean false)
  /// `--units`, over the deck's `output: units:`: of the printed summary and the worst
  /// point's and every point's results directory (study.csv and summary.json keep the
  /// columns' units, which they name).
  OutputUnits units;
};

struct DesignStudyOutcome {
  bool writer = true;  ///< false on MPI ranks other than 0, which write and report nothing
  std::filesystem::path dir;
  long long points = 0, failed = 0;  ///< rows in the table, and those of failed points
  long long resumed = 0;             ///< rows taken from the study resumed
  double seconds = 0;  ///< wall time of the whole study, writing included
  /// Where the points' time went, summed over the points solved here (PointCost), and the
  /// time spent writing their rows and adding them to the summary.
  PointCost cost;
  double rowSeconds = 0;
  int threads = 1;
  RankReport ranks;
  int signal = 0;         ///< the signal that stopped the study, 0 when none did
  PointRanges missing;    ///< points without a row (a stopped study's)
  bool worstWritten = false;  ///< worst/ holds the worst point's results
  std::string resumeNote;     ///< what resuming did beyond the table ("" when nothing)
  /// The time spent solving each point in full and writing its results directory
  /// (--point-files), summed over the points.
  double pointFileSeconds = 0;
  Json summary;
  /// The units chosen for the printed summary: the deck's `output: units:` with --units over
  /// them.
  OutputUnits units;
  bool partial() const { return !missing.empty(); }
};

/// Where a study of `deckPath` goes without --out: out/<deck stem>_study.
std::filesystem::path defaultStudyDirectory(const std::string& deckPath);

/// Called after each row is written: (rows done, rows in all).
using StudyProgress = std::function<void(long long done, long long total)>;

/// Reads, solves and writes the study. Throws DeckError for bad input (before anything is
/// written) and std::runtime_error when the results cannot be written; a point's own failure
/// is recorded in its row and the study goes on.
DesignStudyOutcome runDesignStudy(const DesignStudyRequest& request,
                                  const StudyProgress& progress = {});

}  // namespace beamrotor

// `beamrotor study`: a deck solved at every point of a design study (DesignStudy.hpp), its
// table streamed to study.csv as the points finish, then summary.json and the worst point's
// full results (worst/), all in one results directory replaced atomically at the end
// (problems/output/AtomicDirectory). Per-point results directories (points/<k>/) only when
// asked. Under mpirun the ranks share the points (StudyMpi.hpp) and rank 0 writes.
#pragma once

#include <filesystem>
#include <functional>
#include <string>
#include <vector>

#include "problems/deck/study/DesignStudy.hpp"
#include "problems/output/JsonWriter.hpp"
#include "problems/study/StudyPoint.hpp"

namespace beamrotor {

struct DesignStudyRequest {
  std::string deckPath;
  std::vector<std::string> sets;  ///< "NAME=VALUE" overrides, as typed
  std::string formulation;        ///< --formulation, or empty
  StudyCommandLine study;
  std::string outDir;      ///< empty: out/<deck stem>_study
  int threads = 1;         ///< threads over points on this machine (per MPI rank)
  bool pointFiles = false; ///< also every point's results directory (no charts), points/<k>/
  bool fullPath = false;   ///< read the deck in full at every point (StudyPlan::lean false)
};

struct DesignStudyOutcome {
  bool writer = true;  ///< false on MPI ranks other than 0, which write and report nothing
  std::filesystem::path dir;
  long long points = 0, failed = 0;
  double seconds = 0;  ///< wall time of the whole study, writing included
  /// Where the points' time went, summed over the points (PointCost), and the time spent
  /// writing their rows and adding them to the summary.
  PointCost cost;
  double rowSeconds = 0;
  /// The time spent solving each point in full and writing its results directory
  /// (--point-files), summed over the points.
  double pointFileSeconds = 0;
  Json summary;
};

/// Called after each row is written: (rows done, rows in all).
using StudyProgress = std::function<void(long long done, long long total)>;

/// Reads, solves and writes the study. Throws DeckError for bad input (before anything is
/// written) and std::runtime_error when the results cannot be written; a point's own failure
/// is recorded in its row and the study goes on.
DesignStudyOutcome runDesignStudy(const DesignStudyRequest& request,
                                  const StudyProgress& progress = {});

}  // namespace beamrotor

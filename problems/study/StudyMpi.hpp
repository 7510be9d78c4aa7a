// A design study across MPI ranks (Open MPI; compiled when CMake finds MPI, BEAMROTOR_MPI).
// Under `mpirun -n N`, rank 0 is the manager: it hands out chunks of points to ranks that ask
// (which send each row as they finish it), solves points itself between messages, restores
// point order and hands the rows to the sink; so the table and summary are those of the serial
// run. Without MPI, or run without mpirun, everything here is the
// threaded study of StudyExecution.hpp. The other ranks first wait for rank 0's word that the
// study is shared out: a rank 0 that refuses the study (or fails) before sharing it still sends
// it, "nothing to do", so that no rank is left waiting for a message that will never come while
// rank 0 waits for it in MPI_Finalize. Every wait for rank 0 is polled and, once the study is
// shared, gives way to a stop.
//
// Stopping: mpirun answers Ctrl-C, a SIGTERM or the loss of a rank (kill -9) alike, with
// SIGCONT to every rank, SIGTERM a second later and SIGKILL a second after that (Open MPI 4.1,
// odls_base_sigkill_timeout). Each rank then starts no new point: rank 0 tells the others to
// stop, takes the rows they finished within kStopAnswerSeconds (less when the ranks that have
// not answered ran on its host and their processes are gone) and hands them on; a rank that
// does not answer in that time is named as lost (with its process id and host, and whether
// that process is gone, when it ran on rank 0's host).
#pragma once

#include <string>
#include <vector>

#include "problems/study/StudyExecution.hpp"

namespace beamrotor {

/// Starts MPI when the process was launched by mpirun (Open MPI's OMPI_COMM_WORLD_SIZE or a
/// PMI/PMIx launcher's environment) and ends it on destruction; does nothing otherwise.
class MpiSession {
 public:
  MpiSession();
  ~MpiSession();
  MpiSession(const MpiSession&) = delete;
  MpiSession& operator=(const MpiSession&) = delete;
  /// This process's rank and the number of ranks (0 and 1 without MPI).
  static int rank();
  static int size();
};

/// The number of ranks mpirun started this process among, and its rank, from the launcher's
/// environment (Open MPI's OMPI_COMM_WORLD_SIZE and _RANK, or PMI_SIZE and PMI_RANK): 1 and 0
/// when not launched by mpirun. Known without starting MPI (and in a build without it), so
/// that commands which do not share work among ranks can refuse to run once per rank.
int launchedRanks();
int launchedRank();

/// True where results are written: without MPI, and on rank 0.
inline bool isStudyManager() { return MpiSession::rank() == 0; }

/// How long rank 0 waits, once the study stops, for the other ranks' last rows (s).
inline constexpr double kStopAnswerSeconds = 0.4;

/// Who took part: the number of ranks, and each rank that did not answer when the study
/// stopped ("rank 1 (pid 7611 on node01): its process is gone").
struct RankReport {
  int ranks = 1;
  std::vector<std::string> lost;
};

/// The points of `todo`: with several MPI ranks shared among them (sink called on rank 0
/// only, in increasing point order; `threads` is then ignored, one point at a time per rank;
/// the other ranks ignore `todo` and take what rank 0 hands out), otherwise solvePoints on
/// this machine. After `stop` (asked before each point, on every rank) no point starts and
/// the rows finished are handed on, gaps and all.
RankReport solvePointsOnRank(const StudyPlan& plan, const DesignPoints& points,
                             const PointRanges& todo, int threads, const RowSink& sink,
                             const StopRequest& stop);

/// A row as bytes and back (the message format between ranks; exposed for its test).
void appendRowBytes(std::string& bytes, const StudyRow& row);
/// Reads the row at `offset` of `bytes`, advancing offset; `shape` gives the vector sizes.
StudyRow readRowBytes(const std::string& bytes, std::size_t& offset, const StudyRow& shape);

}  // namespace beamrotor

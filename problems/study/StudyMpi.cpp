#include "problems/study/StudyMpi.hpp"

#include <signal.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <chrono>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <fstream>
#include <functional>
#include <initializer_list>
#include <map>
#include <stdexcept>
#include <string>
#include <thread>
#include <tuple>

#include "problems/output/files/Interruption.hpp"

#ifdef BEAMROTOR_MPI
#include <mpi.h>
#endif

namespace beamrotor {

namespace {

template <class T>
void appendRaw(std::string& bytes, const T* values, std::size_t count) {
  bytes.append(reinterpret_cast<const char*>(values), count * sizeof(T));
}

template <class T>
void readRaw(const std::string& bytes, std::size_t& offset, T* values, std::size_t count) {
  if (offset + count * sizeof(T) > bytes.size()) throw std::runtime_error("short study message");
  std::memcpy(values, bytes.data() + offset, count * sizeof(T));
  offset += count * sizeof(T);
}

}  // namespace

void appendRowBytes(std::string& bytes, const StudyRow& row) {
  const std::int64_t index = row.index;
  appendRaw(bytes, &index, 1);
  appendRaw(bytes, row.parameters.data(), row.parameters.size());
  appendRaw(bytes, row.outputs.data(), row.outputs.size());
  appendRaw(bytes, row.checks.data(), row.checks.size());
  appendRaw(bytes, row.passed.data(), row.passed.size());
  appendRaw(bytes, &row.cost, 1);
  const std::uint32_t length = std::uint32_t(row.status.size());
  appendRaw(bytes, &length, 1);
  bytes += row.status;
}

StudyRow readRowBytes(const std::string& bytes, std::size_t& offset, const StudyRow& shape) {
  StudyRow row = shape;
  std::int64_t index = 0;
  readRaw(bytes, offset, &index, 1);
  row.index = index;
  readRaw(bytes, offset, row.parameters.data(), row.parameters.size());
  readRaw(bytes, offset, row.outputs.data(), row.outputs.size());
  readRaw(bytes, offset, row.checks.data(), row.checks.size());
  readRaw(bytes, offset, row.passed.data(), row.passed.size());
  readRaw(bytes, offset, &row.cost, 1);
  std::uint32_t length = 0;
  readRaw(bytes, offset, &length, 1);
  row.status.resize(length);
  readRaw(bytes, offset, row.status.data(), length);
  return row;
}

namespace {

/// A positive whole number from the first of `names` set in the environment, else `absent`.
int launcherNumber(std::initializer_list<const char*> names, int absent) {
  for (const char* name : names)
    if (const char* text = std::getenv(name)) {
      char* end = nullptr;
      const long value = std::strtol(text, &end, 10);
      if (end != text && *end == '\0' && value >= 0 && value < (1L << 30)) return int(value);
    }
  return absent;
}

}  // namespace

int launchedRanks() {
  return std::max(1, launcherNumber({"OMPI_COMM_WORLD_SIZE", "PMI_SIZE"}, 1));
}

int launchedRank() {
  return launcherNumber({"OMPI_COMM_WORLD_RANK", "PMI_RANK"}, 0);
}

#ifndef BEAMROTOR_MPI

MpiSession::MpiSession() {}
MpiSession::~MpiSession() {}
int MpiSession::rank() { return 0; }
int MpiSession::size() { return 1; }

RankReport solvePointsOnRank(const StudyPlan& plan, const DesignPoints& points,
                             const PointRanges& todo, int threads, const RowSink& sink,
                             const StopRequest& stop) {
  solvePoints(plan, points, todo, threads, sink, stop);
  return {};
}

#else

namespace {

bool& mpiStarted() {
  static bool started = false;
  return started;
}

// Each row travels on its own as soon as it is solved: rank 0 has it even if its rank is then
// lost, and a message of one row stays below the transports' eager limit, so rank 0 never has
// to read it out of a process that has died meanwhile (which Open MPI cannot survive).
constexpr int kRowTag = 1;      // worker -> manager: one finished row
constexpr int kChunkTag = 2;    // manager -> worker: [begin, end), empty to stop
constexpr int kStopTag = 3;     // manager -> worker: stop after the point in progress
constexpr int kAskTag = 4;      // worker -> manager: its chunk is done, it asks for another
constexpr int kStoppedTag = 6;  // worker -> manager: it stopped before its chunk was done
constexpr int kReleaseTag = 5;   // manager -> worker: the results are written, end now
constexpr int kStartTag = 7;     // manager -> worker: 1 the study is shared out, 0 nothing to do

/// Rank 0 told the other ranks whether there is work (kStartTag). Until it has, they wait for
/// that word alone: rank 0 can refuse the study before sharing it (--resume of a finished
/// study, an output directory it may not replace) and must then still let them go.
bool& workersStarted() {
  static bool started = false;
  return started;
}

/// How long a stopped rank waits for rank 0 to write the results (s); mpirun ends it sooner.
constexpr double kReleaseWaitSeconds = 10;

bool launchedByMpirun() {
  for (const char* name : {"OMPI_COMM_WORLD_SIZE", "PMIX_RANK", "PMI_RANK"})
    if (std::getenv(name)) return true;
  return false;
}

/// A rank's process, as the others may name it.
struct RankProcess {
  std::int32_t pid = 0;
  char host[MPI_MAX_PROCESSOR_NAME] = {};
};

/// Every rank's process, on rank 0 (collective: every rank calls it).
std::vector<RankProcess> gatherProcesses() {
  RankProcess mine;
  mine.pid = std::int32_t(::getpid());
  int length = 0;
  MPI_Get_processor_name(mine.host, &length);
  std::vector<RankProcess> all(std::size_t(MpiSession::size()));
  MPI_Gather(&mine, int(sizeof mine), MPI_BYTE, all.data(), int(sizeof mine), MPI_BYTE, 0,
             MPI_COMM_WORLD);
  return all;
}

/// Whether process `pid` of this host has ended (gone, or a zombie not yet reaped).
bool processGone(int pid) {
  if (::kill(pid, 0) != 0) return errno == ESRCH;
  std::ifstream stat("/proc/" + std::to_string(pid) + "/stat");
  std::string text;
  std::getline(stat, text);
  const std::size_t close = text.rfind(')');
  return close != std::string::npos && close + 2 < text.size() && text[close + 2] == 'Z';
}

std::string lostRank(int rank, const RankProcess& process, const RankProcess& manager) {
  std::string text = "rank " + std::to_string(rank) + " (pid " + std::to_string(process.pid) +
                     " on " + process.host + "): ";
  if (std::strcmp(process.host, manager.host) == 0 && processGone(process.pid))
    return text + "its process is gone (killed?)";
  char seconds[32];
  std::snprintf(seconds, sizeof seconds, "%.1f", kStopAnswerSeconds);
  return text + "did not answer within " + seconds + " s of the stop";
}

/// A stop message from rank 0 waiting for this rank (taken when there is one).
bool stopMessage() {
  int waiting = 0;
  MPI_Iprobe(0, kStopTag, MPI_COMM_WORLD, &waiting, MPI_STATUS_IGNORE);
  if (!waiting) return false;
  std::int64_t word = 0;
  MPI_Recv(&word, 1, MPI_INT64_T, 0, kStopTag, MPI_COMM_WORLD, MPI_STATUS_IGNORE);
  return true;
}

/// Waits for a message from rank 0 with `tag` (polled, so that the process stays responsive)
/// and takes it into `words`; gives up, false, when `giveUp` says so first.
bool awaitFromManager(int tag, std::int64_t* words, int count,
                      const std::function<bool()>& giveUp) {
  for (;;) {
    int waiting = 0;
    MPI_Iprobe(0, tag, MPI_COMM_WORLD, &waiting, MPI_STATUS_IGNORE);
    if (waiting) {
      MPI_Recv(words, count, MPI_INT64_T, 0, tag, MPI_COMM_WORLD, MPI_STATUS_IGNORE);
      return true;
    }
    if (giveUp()) return false;
    std::this_thread::sleep_for(std::chrono::microseconds(200));
  }
}

void studyWorker(const StudyPlan& plan, const DesignPoints& points, const StopRequest& stop) {
  // Rank 0 always sends this word (or dies, and mpirun ends this rank): no stop is taken here,
  // since a rank 0 about to share the study would wait for this rank in the gather.
  std::int64_t start = 0;
  awaitFromManager(kStartTag, &start, 1, [] { return false; });
  if (start == 0) return;
  gatherProcesses();
  const PointSolver solver(plan);
  std::string row;
  const auto stopped = [&] {
    if (!stop() && !stopMessage()) return false;
    MPI_Send(nullptr, 0, MPI_BYTE, 0, kStoppedTag, MPI_COMM_WORLD);
    return true;
  };
  for (;;) {
    MPI_Send(nullptr, 0, MPI_BYTE, 0, kAskTag, MPI_COMM_WORLD);
    // Stopped while waiting: rank 0 may be stopping too, and answer no more.
    std::int64_t range[2];
    if (!awaitFromManager(kChunkTag, range, 2, stopped)) return;
    if (range[0] >= range[1]) return;
    for (std::int64_t i = range[0]; i < range[1]; ++i) {
      if (stopped()) return;
      row.clear();
      appendRowBytes(row, solver.solve(i, points.at(i)));
      MPI_Send(row.data(), int(row.size()), MPI_BYTE, 0, kRowTag, MPI_COMM_WORLD);
    }
  }
}

double secondsNow() {
  return std::chrono::duration<double>(std::chrono::steady_clock::now().time_since_epoch())
      .count();
}

/// Rank 0: hands out chunks of `todo` (each inside one run of consecutive points, as index
/// ranges), solves its own between messages, hands rows on in order as they become
/// consecutive, and after a stop collects what the others finished.
RankReport studyManager(const StudyPlan& plan, const DesignPoints& points,
                        const PointRanges& todo, const RowSink& sink, const StopRequest& stop,
                        const std::vector<RankProcess>& processes) {
  const long long n = todo.size();
  const int ranks = MpiSession::size();
  const long long chunk = studyChunk(n, ranks);
  const StudyRow shape = blankRow(plan);
  const PointSolver solver(plan);
  std::map<long long, StudyRow> ready;
  long long handedOut = 0;  // positions in todo
  long long nextOut = 0;    // the position the sink gets next
  long long ownBegin = 0, ownEnd = 0;  // the index range rank 0 is solving itself
  std::vector<char> finished(std::size_t(ranks), 0);
  finished[0] = 1;
  bool stopping = false;
  double deadline = 0;
  static const std::int64_t stopWord = 1;  // outlives the unawaited sends
  auto takeChunk = [&]() -> std::pair<long long, long long> {
    if (stopping || handedOut >= n) return {0, 0};
    const long long begin = todo.at(handedOut);
    const long long end = std::min(todo.lastInRun(handedOut) + 1, begin + chunk);
    handedOut += end - begin;
    return {begin, end};
  };
  auto flush = [&](bool all) {
    while (!ready.empty() &&
           (all || (nextOut < n && ready.begin()->first == todo.at(nextOut)))) {
      sink(ready.begin()->second);
      ready.erase(ready.begin());
      ++nextOut;
    }
  };
  auto receive = [&](const MPI_Status& status) {
    int bytes = 0;
    MPI_Get_count(&status, MPI_BYTE, &bytes);
    std::string message(std::size_t(bytes), '\0');
    MPI_Recv(message.data(), bytes, MPI_BYTE, status.MPI_SOURCE, status.MPI_TAG, MPI_COMM_WORLD,
             MPI_STATUS_IGNORE);
    if (status.MPI_TAG == kRowTag) {
      std::size_t offset = 0;
      StudyRow row = readRowBytes(message, offset, shape);
      ready.emplace(row.index, std::move(row));
      return;
    }
    if (status.MPI_TAG == kStoppedTag) {
      finished[std::size_t(status.MPI_SOURCE)] = 1;
      return;
    }
    const auto [begin, end] = takeChunk();
    const std::int64_t range[2] = {begin, end};
    if (begin >= end) finished[std::size_t(status.MPI_SOURCE)] = 1;
    MPI_Send(range, 2, MPI_INT64_T, status.MPI_SOURCE, kChunkTag, MPI_COMM_WORLD);
  };
  const auto allFinished = [&] {
    return std::all_of(finished.begin(), finished.end(), [](char f) { return f != 0; });
  };
  // Stopping: a rank of this host whose process is gone will not answer; mpirun's SIGKILL
  // comes about a second after its SIGTERM, so that time is left for writing the results.
  const auto othersGone = [&] {
    for (int r = 1; r < ranks; ++r)
      if (!finished[std::size_t(r)] &&
          (std::strcmp(processes[std::size_t(r)].host, processes[0].host) != 0 ||
           !processGone(processes[std::size_t(r)].pid)))
        return false;
    return true;
  };
  for (;;) {
    if (!stopping && stop()) {
      stopping = true;
      deadline = secondsNow() + kStopAnswerSeconds;
      for (int r = 1; r < ranks; ++r) {
        if (finished[std::size_t(r)]) continue;
        MPI_Request request;
        MPI_Isend(&stopWord, 1, MPI_INT64_T, r, kStopTag, MPI_COMM_WORLD, &request);
        MPI_Request_free(&request);
      }
    }
    int waiting = 0;
    MPI_Status status;
    MPI_Iprobe(MPI_ANY_SOURCE, MPI_ANY_TAG, MPI_COMM_WORLD, &waiting, &status);
    if (waiting && (status.MPI_TAG == kRowTag || status.MPI_TAG == kAskTag ||
                    status.MPI_TAG == kStoppedTag)) {
      receive(status);
    } else if (!stopping && ownBegin < ownEnd) {
      ready.emplace(ownBegin, solver.solve(ownBegin, points.at(ownBegin)));
      ++ownBegin;
    } else if (!stopping && handedOut < n) {
      std::tie(ownBegin, ownEnd) = takeChunk();
    } else if (allFinished() || (stopping && (secondsNow() > deadline || othersGone()))) {
      break;
    } else {
      // Waiting for the others: polled, not blocked in MPI_Probe, so that a signal (or a
      // rank that is gone) is seen.
      std::this_thread::sleep_for(std::chrono::microseconds(200));
    }
    flush(false);
  }
  flush(true);
  RankReport report;
  report.ranks = ranks;
  for (int r = 1; r < ranks; ++r)
    if (!finished[std::size_t(r)])
      report.lost.push_back(lostRank(r, processes[std::size_t(r)], processes[0]));
  return report;
}

}  // namespace

MpiSession::MpiSession() {
  int initialised = 0;
  MPI_Initialized(&initialised);
  if (initialised || !launchedByMpirun()) return;
  MPI_Init(nullptr, nullptr);
  // A rank that is gone must not take rank 0 down with it before the rows are written.
  MPI_Comm_set_errhandler(MPI_COMM_WORLD, MPI_ERRORS_RETURN);
  mpiStarted() = true;
}

MpiSession::~MpiSession() {
  if (!mpiStarted()) return;
  mpiStarted() = false;
  int rank = 0, ranks = 1;
  MPI_Comm_rank(MPI_COMM_WORLD, &rank);
  MPI_Comm_size(MPI_COMM_WORLD, &ranks);
  // Rank 0 ended before sharing a study (it refused it, or failed first): the others are
  // waiting for its first word, and would wait for ever while it waits in MPI_Finalize.
  if (rank == 0 && !workersStarted()) {
    static const std::int64_t nothingToDo = 0;
    for (int r = 1; r < ranks; ++r)
      MPI_Send(&nothingToDo, 1, MPI_INT64_T, r, kStartTag, MPI_COMM_WORLD);
  }
  if (pendingInterruption() == 0) {
    MPI_Finalize();
    return;
  }
  // Stopped by a signal. A rank may be gone, so MPI_Finalize could wait for ever; each process
  // ends by the signal right after (main). But mpirun kills every rank at once when one of
  // them ends: the others wait until rank 0 has written the results and lets them go.
  static const std::int64_t releaseWord = 1;  // outlives the unawaited sends
  if (rank == 0) {
    for (int r = 1; r < ranks; ++r) {
      MPI_Request request;
      MPI_Isend(&releaseWord, 1, MPI_INT64_T, r, kReleaseTag, MPI_COMM_WORLD, &request);
      MPI_Request_free(&request);
    }
    return;
  }
  const double until = secondsNow() + kReleaseWaitSeconds;
  for (int released = 0; !released && secondsNow() < until;) {
    MPI_Iprobe(0, kReleaseTag, MPI_COMM_WORLD, &released, MPI_STATUS_IGNORE);
    std::this_thread::sleep_for(std::chrono::milliseconds(1));
  }
}

int MpiSession::rank() {
  if (!mpiStarted()) return 0;
  int r = 0;
  MPI_Comm_rank(MPI_COMM_WORLD, &r);
  return r;
}

int MpiSession::size() {
  if (!mpiStarted()) return 1;
  int s = 1;
  MPI_Comm_size(MPI_COMM_WORLD, &s);
  return s;
}

RankReport solvePointsOnRank(const StudyPlan& plan, const DesignPoints& points,
                             const PointRanges& todo, int threads, const RowSink& sink,
                             const StopRequest& stop) {
  if (MpiSession::size() <= 1) {
    solvePoints(plan, points, todo, threads, sink, stop);
    return {};
  }
  try {
    if (MpiSession::rank() != 0) {
      studyWorker(plan, points, stop);
      return {MpiSession::size(), {}};
    }
    workersStarted() = true;
    static const std::int64_t shared = 1;
    for (int r = 1; r < MpiSession::size(); ++r)
      MPI_Send(&shared, 1, MPI_INT64_T, r, kStartTag, MPI_COMM_WORLD);
    return studyManager(plan, points, todo, sink, stop, gatherProcesses());
  } catch (const std::exception& e) {
    // A rank that fails midway leaves the others waiting for its messages: end them all.
    std::fprintf(stderr, "beamrotor: %s\n", e.what());
    MPI_Abort(MPI_COMM_WORLD, 1);
  }
  return {};
}

#endif

}  // namespace beamrotor

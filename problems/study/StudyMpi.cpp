#include "problems/study/StudyMpi.hpp"

#include <algorithm>
#include <cstdint>
#include <initializer_list>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <map>
#include <stdexcept>
#include <string>

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

void solvePointsOnRank(const StudyPlan& plan, const DesignPoints& points, int threads,
                       const RowSink& sink) {
  solvePoints(plan, points, threads, sink);
}

#else

namespace {

bool& mpiStarted() {
  static bool started = false;
  return started;
}

constexpr int kRowsTag = 1;   // worker -> manager: finished rows (none on the first request)
constexpr int kChunkTag = 2;  // manager -> worker: [begin, end), empty to stop

bool launchedByMpirun() {
  for (const char* name : {"OMPI_COMM_WORLD_SIZE", "PMIX_RANK", "PMI_RANK"})
    if (std::getenv(name)) return true;
  return false;
}

StudyRow rowShape(const StudyPlan& plan) {
  StudyRow shape;
  shape.parameters.resize(plan.parameterNames.size());
  shape.outputs.resize(plan.spec.outputs.size());
  shape.checks.resize(plan.checkNames.size());
  shape.passed.resize(plan.checkNames.size());
  return shape;
}

void studyWorker(const StudyPlan& plan, const DesignPoints& points) {
  const PointSolver solver(plan);
  std::string rows;
  for (;;) {
    MPI_Send(rows.data(), int(rows.size()), MPI_BYTE, 0, kRowsTag, MPI_COMM_WORLD);
    std::int64_t range[2];
    MPI_Recv(range, 2, MPI_INT64_T, 0, kChunkTag, MPI_COMM_WORLD, MPI_STATUS_IGNORE);
    if (range[0] >= range[1]) return;
    rows.clear();
    for (std::int64_t i = range[0]; i < range[1]; ++i)
      appendRowBytes(rows, solver.solve(i, points.at(i)));
  }
}

void studyManager(const StudyPlan& plan, const DesignPoints& points, const RowSink& sink) {
  const long long n = points.size();
  const long long chunk = studyChunk(n, MpiSession::size());
  const StudyRow shape = rowShape(plan);
  const PointSolver solver(plan);
  std::map<long long, StudyRow> ready;
  long long handedOut = 0, next = 0;
  long long ownBegin = 0, ownEnd = 0;  // the chunk rank 0 is solving itself
  int stopped = 0;
  const int workers = MpiSession::size() - 1;
  auto flush = [&] {
    for (auto it = ready.find(next); it != ready.end(); it = ready.find(next)) {
      sink(it->second);
      ready.erase(it);
      ++next;
    }
  };
  auto serve = [&](const MPI_Status& status) {
    int bytes = 0;
    MPI_Get_count(&status, MPI_BYTE, &bytes);
    std::string rows(std::size_t(bytes), '\0');
    MPI_Recv(rows.data(), bytes, MPI_BYTE, status.MPI_SOURCE, kRowsTag, MPI_COMM_WORLD,
             MPI_STATUS_IGNORE);
    for (std::size_t offset = 0; offset < rows.size();) {
      StudyRow row = readRowBytes(rows, offset, shape);
      ready.emplace(row.index, std::move(row));
    }
    std::int64_t range[2] = {handedOut, std::min(n, handedOut + chunk)};
    handedOut = range[1];
    if (range[0] >= range[1]) ++stopped;
    MPI_Send(range, 2, MPI_INT64_T, status.MPI_SOURCE, kChunkTag, MPI_COMM_WORLD);
  };
  while (next < n || stopped < workers) {
    int waiting = 0;
    MPI_Status status;
    MPI_Iprobe(MPI_ANY_SOURCE, kRowsTag, MPI_COMM_WORLD, &waiting, &status);
    if (waiting) {
      serve(status);
    } else if (ownBegin < ownEnd) {
      ready.emplace(ownBegin, solver.solve(ownBegin, points.at(ownBegin)));
      ++ownBegin;
    } else if (handedOut < n) {
      ownBegin = handedOut;
      ownEnd = handedOut = std::min(n, handedOut + chunk);
    } else {
      MPI_Probe(MPI_ANY_SOURCE, kRowsTag, MPI_COMM_WORLD, &status);  // wait for the others
      serve(status);
    }
    flush();
  }
}

}  // namespace

MpiSession::MpiSession() {
  int initialised = 0;
  MPI_Initialized(&initialised);
  if (initialised || !launchedByMpirun()) return;
  MPI_Init(nullptr, nullptr);
  mpiStarted() = true;
}

MpiSession::~MpiSession() {
  if (mpiStarted()) MPI_Finalize();
  mpiStarted() = false;
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

void solvePointsOnRank(const StudyPlan& plan, const DesignPoints& points, int threads,
                       const RowSink& sink) {
  if (MpiSession::size() <= 1) return solvePoints(plan, points, threads, sink);
  if (MpiSession::rank() != 0) return studyWorker(plan, points);
  try {
    studyManager(plan, points, sink);
  } catch (const std::exception& e) {
    // The other ranks wait for chunks that will never come: end them all.
    std::fprintf(stderr, "beamrotor: %s\n", e.what());
    MPI_Abort(MPI_COMM_WORLD, 1);
  }
}

#endif

}  // namespace beamrotor

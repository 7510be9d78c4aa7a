#include "problems/study/StudyExecution.hpp"

#include <algorithm>
#include <atomic>
#include <condition_variable>
#include <exception>
#include <map>
#include <mutex>
#include <thread>

namespace beamrotor {

long long studyChunk(long long points, int workers) {
  return std::clamp(points / (64LL * std::max(workers, 1)), 1LL, 256LL);
}

namespace {

/// Rows finished out of order, waiting for the ones before them.
struct ReorderBuffer {
  std::mutex lock;
  std::condition_variable changed;
  std::map<long long, StudyRow> ready;
  long long next = 0;  ///< the row the sink gets next
  bool stopped = false;
  std::exception_ptr failure;
  /// Stops every thread, keeping the first failure.
  void stop(std::exception_ptr why) {
    std::lock_guard<std::mutex> guard(lock);
    if (!failure) failure = why;
    stopped = true;
    changed.notify_all();
  }
};

}  // namespace

void solvePoints(const StudyPlan& plan, const DesignPoints& points, int threads,
                 const RowSink& sink) {
  const long long n = points.size();
  if (threads <= 1) {
    const PointSolver solver(plan);
    for (long long i = 0; i < n; ++i) sink(solver.solve(i, points.at(i)));
    return;
  }
  const long long chunk = studyChunk(n, threads);
  // Back pressure: a worker more than this far ahead of the sink waits.
  const long long window = std::max(4096LL, 4 * chunk * threads);
  std::atomic<long long> handedOut{0};
  ReorderBuffer buffer;
  auto work = [&] {
    try {
      const PointSolver solver(plan);
      for (;;) {
        const long long begin = handedOut.fetch_add(chunk);
        if (begin >= n) return;
        for (long long i = begin; i < std::min(n, begin + chunk); ++i) {
          StudyRow row = solver.solve(i, points.at(i));
          std::unique_lock<std::mutex> guard(buffer.lock);
          buffer.changed.wait(guard, [&] { return buffer.stopped || i - buffer.next < window; });
          if (buffer.stopped) return;
          buffer.ready.emplace(i, std::move(row));
          buffer.changed.notify_all();
        }
      }
    } catch (...) {
      buffer.stop(std::current_exception());
    }
  };
  std::vector<std::thread> workers;
  for (int t = 0; t < threads; ++t) workers.emplace_back(work);
  try {
    while (true) {
      std::unique_lock<std::mutex> guard(buffer.lock);
      if (buffer.next >= n) break;
      buffer.changed.wait(guard, [&] { return buffer.stopped || buffer.ready.count(buffer.next); });
      if (buffer.stopped) break;
      const auto it = buffer.ready.find(buffer.next);
      StudyRow row = std::move(it->second);
      buffer.ready.erase(it);
      guard.unlock();
      sink(row);
      guard.lock();
      ++buffer.next;
      buffer.changed.notify_all();
    }
  } catch (...) {
    buffer.stop(std::current_exception());
  }
  for (std::thread& t : workers) t.join();
  if (buffer.failure) std::rethrow_exception(buffer.failure);
}

}  // namespace beamrotor

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

/// Rows finished out of order, waiting for the ones before them; positions count the points
/// of the study's `todo` in order.
struct ReorderBuffer {
  std::mutex lock;
  std::condition_variable changed;
  std::map<long long, StudyRow> ready;  ///< by position
  long long next = 0;                   ///< the position the sink gets next
  int working = 0;                      ///< workers still taking points
  bool halted = false;                  ///< a worker saw the stop request
  bool failed = false;
  std::exception_ptr failure;
  /// Stops every thread, keeping the first failure.
  void fail(std::exception_ptr why) {
    std::lock_guard<std::mutex> guard(lock);
    if (!failure) failure = why;
    failed = true;
    changed.notify_all();
  }
};

}  // namespace

void solvePoints(const StudyPlan& plan, const DesignPoints& points, const PointRanges& todo,
                 int threads, const RowSink& sink, const StopRequest& stop) {
  const long long n = todo.size();
  if (threads <= 1) {
    const PointSolver solver(plan);
    for (long long p = 0; p < n && !stop(); ++p) {
      const long long i = todo.at(p);
      sink(solver.solve(i, points.at(i)));
    }
    return;
  }
  const long long chunk = studyChunk(n, threads);
  // Back pressure: a worker more than this far ahead of the sink waits.
  const long long window = std::max(4096LL, 4 * chunk * threads);
  std::atomic<long long> handedOut{0};
  ReorderBuffer buffer;
  buffer.working = threads;
  auto work = [&] {
    try {
      const PointSolver solver(plan);
      for (bool more = true; more;) {
        const long long begin = handedOut.fetch_add(chunk);
        more = begin < n;
        for (long long p = begin; more && p < std::min(n, begin + chunk); ++p) {
          if (stop()) {
            std::lock_guard<std::mutex> guard(buffer.lock);
            buffer.halted = true;
            buffer.changed.notify_all();
            more = false;
            break;
          }
          const long long i = todo.at(p);
          StudyRow row = solver.solve(i, points.at(i));
          std::unique_lock<std::mutex> guard(buffer.lock);
          buffer.changed.wait(guard, [&] {
            return buffer.failed || buffer.halted || p - buffer.next < window;
          });
          if (buffer.failed) return;
          buffer.ready.emplace(p, std::move(row));
          buffer.changed.notify_all();
          more = !buffer.halted;
        }
      }
    } catch (...) {
      buffer.fail(std::current_exception());
    }
    std::lock_guard<std::mutex> guard(buffer.lock);
    --buffer.working;
    buffer.changed.notify_all();
  };
  std::vector<std::thread> workers;
  for (int t = 0; t < threads; ++t) workers.emplace_back(work);
  try {
    while (true) {
      std::unique_lock<std::mutex> guard(buffer.lock);
      buffer.changed.wait(guard, [&] {
        return buffer.failed || buffer.ready.count(buffer.next) || buffer.working == 0;
      });
      if (buffer.failed || buffer.ready.empty()) break;  // failed, or every row handed on
      // The next row, or after a stop (every worker gone) the first beyond a gap.
      const auto it = buffer.ready.begin();
      StudyRow row = std::move(it->second);
      buffer.next = it->first + 1;
      buffer.ready.erase(it);
      guard.unlock();
      sink(row);
      guard.lock();
      buffer.changed.notify_all();
    }
  } catch (...) {
    buffer.fail(std::current_exception());
  }
  for (std::thread& t : workers) t.join();
  if (buffer.failure) std::rethrow_exception(buffer.failure);
}

}  // namespace beamrotor

// Work split into parts that run on the machine's cores. Each part owns a range (of elements,
// equations or columns), so that no two parts write the same place and every sum is taken in
// the same order whatever the number of parts: results are the same to the last bit on one
// core or many.
#pragma once

#include <algorithm>
#include <atomic>
#include <cstddef>
#include <exception>
#include <new>
#include <optional>
#include <system_error>
#include <thread>
#include <vector>

namespace beamrotor {

/// Cores this process may use: BEAMROTOR_THREADS when it is a positive number, else the CPU
/// affinity (which taskset, cgroups and batch schedulers narrow).
int usableCores();

/// How many parts a pass over `items` items (elements, equations) runs in: one per usable
/// core, and at most one per 50 000 items: starting a thread costs about what a few thousand
/// elements take, and a study's small models stay on one thread each.
int partsFor(std::size_t items);

/// Bounds 0 = b_0 <= b_1 <= ... <= b_parts = n of `parts` ranges of [0, n) of equal length.
std::vector<int> evenRanges(int n, int parts);

/// Runs work(0), ..., work(parts - 1) on as many threads (the last on the caller's) and then
/// rethrows the exception of the first part that threw, if any. A part whose thread cannot be
/// started (a process limit, address space under `ulimit -v`) runs on the caller's thread:
/// the parts own their ranges, so the result is the same.
template <class Work>
void runParts(int parts, Work&& work) {
  std::vector<std::exception_ptr> failures(parts);
  const auto guarded = [&](int part) {
    try {
      work(part);
    } catch (...) {
      failures[part] = std::current_exception();
    }
  };
  std::vector<std::thread> threads;
  int started = 0;
  try {
    threads.reserve(std::size_t(std::max(parts - 1, 0)));
    for (; started + 1 < parts; ++started) threads.emplace_back(guarded, started);
  } catch (const std::system_error&) {
  } catch (const std::bad_alloc&) {
  }
  for (int part = started; part < parts; ++part) guarded(part);
  for (std::thread& t : threads) t.join();
  for (const std::exception_ptr& failure : failures)
    if (failure) std::rethrow_exception(failure);
}

/// Runs first() and second() at the same time when `items` items make two parts worth it
/// (first() on a thread of its own), else one after the other; exceptions as runParts.
template <class First, class Second>
void runTogether(std::size_t items, First&& first, Second&& second) {
  if (partsFor(items) < 2) {
    first();
    second();
    return;
  }
  runParts(2, [&](int part) { part == 0 ? first() : second(); });
}

/// The results of item(0, worker), ..., item(n - 1, worker), in the order of i, computed on up
/// to `workers` threads (the last on the caller's); `worker` (0 to workers - 1) names the
/// thread an item runs on, for what each thread keeps of its own. The items are handed out in
/// ascending order and none after one that has thrown is started, so every item before the
/// first that throws runs, and that item's exception is rethrown: the one a loop over the
/// items would throw. Each item must be the same computation on any thread.
template <class Item>
auto resultsSideBySide(int n, int workers, Item&& item) {
  using Result = decltype(item(0, 0));
  std::vector<std::optional<Result>> results(std::size_t(std::max(n, 0)));
  std::vector<std::exception_ptr> failures(results.size());
  std::atomic<int> next{0}, firstFailed{n};
  runParts(std::max(1, std::min(workers, n)), [&](int worker) {
    for (int i = next++; i < firstFailed; i = next++) {
      try {
        results[std::size_t(i)].emplace(item(i, worker));
      } catch (...) {
        failures[std::size_t(i)] = std::current_exception();
        for (int seen = firstFailed; i < seen && !firstFailed.compare_exchange_weak(seen, i);) {
        }
      }
    }
  });
  for (const std::exception_ptr& failure : failures)
    if (failure) std::rethrow_exception(failure);
  std::vector<Result> out;
  out.reserve(results.size());
  for (std::optional<Result>& result : results) out.push_back(std::move(*result));
  return out;
}

/// What pick(i, out) appends to `out` for i = 0, ..., n - 1, in the order of i: each part
/// picks from its own range of i into a list of its own, and the lists are joined.
template <class Pick>
std::vector<int> pickInParts(int n, Pick&& pick) {
  const std::vector<int> bounds = evenRanges(n, partsFor(std::size_t(std::max(n, 0))));
  std::vector<std::vector<int>> picked(bounds.size() - 1);
  runParts(int(picked.size()), [&](int part) {
    for (int i = bounds[part]; i < bounds[part + 1]; ++i) pick(i, picked[part]);
  });
  std::vector<int> all;
  for (const std::vector<int>& list : picked) all.insert(all.end(), list.begin(), list.end());
  return all;
}

/// Runs work(first, end) over the ranges of evenRanges(n, partsFor(n)).
template <class Work>
void forEvenParts(int n, Work&& work) {
  const std::vector<int> bounds = evenRanges(n, partsFor(std::size_t(std::max(n, 0))));
  runParts(int(bounds.size()) - 1, [&](int part) { work(bounds[part], bounds[part + 1]); });
}

}  // namespace beamrotor

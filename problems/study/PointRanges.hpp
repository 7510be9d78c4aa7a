// A set of study points kept as sorted, disjoint runs of consecutive indices: the points a
// study still has to solve (all of them, or what a resumed study lacks) and the points an
// interrupted one is missing. A grid of 10^8 points interrupted on a few threads is a handful
// of runs, not 10^8 indices.
#pragma once

#include <string>
#include <vector>

namespace beamrotor {

class PointRanges {
 public:
  /// One run of consecutive points, [first, last].
  struct Run {
    long long first = 0, last = 0;
  };
  PointRanges() = default;
  /// Every point of [0, count).
  static PointRanges all(long long count);
  /// Adds `index`, which must lie after every point already held (or be one of them).
  void append(long long index);
  /// The points of [0, count) not held here.
  PointRanges complement(long long count) const;
  long long size() const { return size_; }
  bool empty() const { return size_ == 0; }
  /// The position-th point held (0 <= position < size()), in increasing order.
  long long at(long long position) const;
  /// The last point of the run that holds the position-th point.
  long long lastInRun(long long position) const;
  const std::vector<Run>& runs() const { return runs_; }
  /// "0-99, 150, 200-210" (runs joined; at most `most` of them, then ", ... and N more").
  std::string text(std::size_t most = 20) const;

 private:
  std::size_t runHolding(long long position) const;
  std::vector<Run> runs_;
  std::vector<long long> before_;  ///< points held in the runs before each run
  long long size_ = 0;
};

}  // namespace beamrotor

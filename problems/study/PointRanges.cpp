#include "problems/study/PointRanges.hpp"

#include <algorithm>
#include <stdexcept>

namespace beamrotor {

PointRanges PointRanges::all(long long count) {
  PointRanges r;
  if (count > 0) {
    r.runs_.push_back({0, count - 1});
    r.before_.push_back(0);
    r.size_ = count;
  }
  return r;
}

void PointRanges::append(long long index) {
  if (!runs_.empty() && index <= runs_.back().last) {
    if (index >= runs_.back().first) return;  // held already
    throw std::logic_error("PointRanges::append: points out of order");
  }
  if (!runs_.empty() && index == runs_.back().last + 1) {
    ++runs_.back().last;
  } else {
    runs_.push_back({index, index});
    before_.push_back(size_);
  }
  ++size_;
}

PointRanges PointRanges::complement(long long count) const {
  PointRanges gaps;
  long long next = 0;  // the first point not yet accounted for
  const auto addGap = [&](long long first, long long last) {
    if (first > last) return;
    gaps.runs_.push_back({first, last});
    gaps.before_.push_back(gaps.size_);
    gaps.size_ += last - first + 1;
  };
  for (const Run& run : runs_) {
    if (run.first >= count) break;
    addGap(next, run.first - 1);
    next = run.last + 1;
  }
  addGap(next, count - 1);
  return gaps;
}

std::size_t PointRanges::runHolding(long long position) const {
  // The last run that starts at or before `position` points in.
  return std::size_t(std::upper_bound(before_.begin(), before_.end(), position) -
                     before_.begin() - 1);
}

long long PointRanges::at(long long position) const {
  const std::size_t k = runHolding(position);
  return runs_[k].first + (position - before_[k]);
}

long long PointRanges::lastInRun(long long position) const {
  return runs_[runHolding(position)].last;
}

std::string PointRanges::text(std::size_t most) const {
  std::string out;
  for (std::size_t k = 0; k < runs_.size() && k < most; ++k) {
    if (k > 0) out += ", ";
    out += std::to_string(runs_[k].first);
    if (runs_[k].last > runs_[k].first) {
      out += '-';
      out += std::to_string(runs_[k].last);
    }
  }
  if (runs_.size() > most) {
    out += out.empty() ? "" : ", ";
    out += "... and ";
    out += std::to_string(runs_.size() - most);
    out += " more";
  }
  return out;
}

}  // namespace beamrotor

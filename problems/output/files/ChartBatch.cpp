#include "problems/output/files/ChartBatch.hpp"

#include <algorithm>

#include "fem/assembly/ParallelParts.hpp"

namespace beamrotor {

namespace {

thread_local ChartBatch* openBatch = nullptr;

}  // namespace

ChartBatch::ChartBatch(ChartFormat format) : format_(format), previous_(openBatch) {
  openBatch = this;
}

ChartBatch::~ChartBatch() { openBatch = previous_; }

ChartBatch* ChartBatch::active() { return openBatch; }

bool ChartBatch::add(const std::filesystem::path& dir, const ChartScript& chart) {
  confinedFileName(chart.name);  // refused now, where the writer asked for it
  if (format_ == ChartFormat::none) return false;
  auto same = std::find_if(charts_.begin(), charts_.end(),
                           [&](const auto& entry) { return entry.first == dir; });
  if (same == charts_.end()) same = charts_.insert(charts_.end(), {dir, {}});
  same->second.push_back(chart);
  return true;
}

int ChartBatch::draw() {
  auto queued = std::move(charts_);
  charts_.clear();
  int drawn = 0;
  for (const auto& [dir, charts] : queued) drawn += drawCharts(dir, charts, format_, usableCores());
  return drawn;
}

}  // namespace beamrotor

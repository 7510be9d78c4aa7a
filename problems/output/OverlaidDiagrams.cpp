#include "problems/output/OverlaidDiagrams.hpp"

#include <algorithm>
#include <cmath>

#include "problems/output/Charts.hpp"

namespace beamrotor {

namespace {

/// The named points at the same place in every run (a point that moves with the swept
/// parameter would need one marker per value).
std::vector<ChartMarker> commonMarkers(const SweepResult& sweep) {
  std::vector<ChartMarker> common;
  for (const ChartMarker& m : namedPointMarkers(*sweep.runs.front().model)) {
    bool everywhere = true;
    for (const RunResult& run : sweep.runs) {
      const auto markers = namedPointMarkers(*run.model);
      everywhere = everywhere && std::any_of(markers.begin(), markers.end(), [&](const auto& o) {
                     return o.name == m.name && std::abs(o.x - m.x) <= 1e-12 * (1 + std::abs(m.x));
                   });
    }
    if (everywhere) common.push_back(m);
  }
  return common;
}

}  // namespace

void drawOverlaidDiagrams(const std::filesystem::path& dir, const std::string& caption,
                          const std::string& chartName, const SweepResult& sweep,
                          const std::vector<const CsvTable*>& fields,
                          const std::vector<std::string>& csvFiles) {
  if (sweep.values.size() > kOverlaidValues || fields.size() != sweep.values.size() ||
      csvFiles.size() != fields.size())
    return;
  std::vector<FieldSeries> series;
  for (std::size_t i = 0; i < fields.size(); ++i)
    series.push_back(
        {fields[i], csvFiles[i], sweep.parameter + " = " + exactDecimal(sweep.values[i])});
  drawChart(dir, staticDiagrams(caption, chartName, series, commonMarkers(sweep)));
}

}  // namespace beamrotor

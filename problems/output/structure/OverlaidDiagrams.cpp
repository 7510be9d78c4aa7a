#include "problems/output/structure/OverlaidDiagrams.hpp"

#include "problems/output/files/ChartParts.hpp"
#include "problems/output/structure/Charts.hpp"

namespace beamrotor {

void drawOverlaidDiagrams(const std::filesystem::path& dir, const std::string& caption,
                          const std::string& chartName, const SweepResult& sweep,
                          const std::vector<const CsvTable*>& fields,
                          const std::vector<std::string>& csvFiles, const OutputUnits& units) {
  if (sweep.values.size() > kOverlaidValues || fields.size() != sweep.values.size() ||
      csvFiles.size() != fields.size())
    return;
  std::vector<FieldSeries> series;
  std::vector<const Model*> models;
  for (const RunResult& run : sweep.runs) models.push_back(run.model.get());
  // The swept values as the deck wrote them (SI), or in the user's unit of their quantity.
  const OutputUnits::Shown value = units.valueIn(sweep.unit, {1, ""});
  for (std::size_t i = 0; i < fields.size(); ++i)
    series.push_back({fields[i], csvFiles[i],
                      sweep.parameter + " = " + labelNumber(sweep.values[i] * value.factor) +
                          (value.unit.empty() ? "" : " " + value.unit)});
  drawChart(dir, staticDiagrams(caption, chartName, series, commonPointMarkers(models),
                                kAllDiagrams, units));
}

}  // namespace beamrotor

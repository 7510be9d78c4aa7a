#include "problems/output/OverlayOutput.hpp"

#include <stdexcept>

#include "problems/output/files/TableUnits.hpp"
#include "problems/output/structure/LineSampling.hpp"
#include "problems/output/structure/Tables.hpp"

namespace beamrotor {

const AnalysisOutcome* overlaidAnalysis(const RunResult& run) {
  if (!run.model->members().empty()) return nullptr;
  for (const AnalysisOutcome& a : run.analyses)
    if (staticsOf(a)) return &a;
  return nullptr;
}

bool writeOverlay(const std::filesystem::path& dir, const std::vector<OverlaidRun>& runs,
                  const std::vector<Diagram>& shown, const OutputUnits& units) {
  std::vector<CsvTable> tables;
  tables.reserve(runs.size());  // FieldSeries point into it
  std::vector<FieldSeries> series;
  std::string caption = "overlay:";
  std::vector<const Model*> models;
  for (const OverlaidRun& r : runs) {
    const AnalysisOutcome* a = overlaidAnalysis(*r.run);
    if (!a) throw std::invalid_argument(r.label + " has no static analysis along a line");
    const std::string file = r.label + "_fields.csv";
    tables.push_back(inUnits(
        staticFieldsTable(file, sampleStatics({*r.run->model, staticsOf(*a)->displacement})),
        units));
    tables.back().write(dir / file);
    series.push_back({&tables.back(), file, r.label});
    models.push_back(r.run->model.get());
    caption += (&r == &runs.front() ? " " : ", ") + r.label + " (" + a->name + ")";
  }
  return drawChart(
      dir, staticDiagrams(caption, "overlay", series, commonPointMarkers(models), shown, units));
}

}  // namespace beamrotor

#include "problems/output/OverlayOutput.hpp"

#include <set>
#include <stdexcept>

#include "problems/deck/parse/DeckError.hpp"
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

CsvTable overlaidTable(const OverlaidRun& r, const OutputUnits& units) {
  const AnalysisOutcome* a = overlaidAnalysis(*r.run);
  if (!a) throw std::invalid_argument(r.label + " has no static analysis along a line");
  return inUnits(staticFieldsTable(r.label + "_fields.csv",
                                   sampleStatics({*r.run->model, staticsOf(*a)->displacement})),
                 units);
}

std::vector<Study> solveOverlaid(const std::vector<std::string>& deckPaths,
                                 const std::vector<std::string>& sets) {
  std::vector<Study> studies;
  std::set<std::string> labels;
  for (const std::string& path : deckPaths) {
    StudyRequest one;
    one.deckPath = path;
    one.sets = sets;
    one.noSweep = true;
    studies.push_back(solveStudy(one));
    const RunResult& run = *studies.back().run;
    if (!overlaidAnalysis(run))
      throw DeckError(path, DeckPlace{0, 0, "analyses"},
                      "has no static analysis along a line to overlay (a frame's members or "
                      "a model without beams have no diagrams along one line)");
    if (!labels.insert(run.deckName).second)
      throw DeckError(path, DeckPlace{0, 0, "overlay"},
                      "is given twice; for several values of one deck's parameter use "
                      "`beamrotor solve DECK --sweep NAME=V1,V2`");
  }
  return studies;
}

std::vector<Diagram> overlaidDiagrams(const std::string& quantity) {
  std::vector<Diagram> shown;
  for (Diagram d : kAllDiagrams)
    if (quantity == "all" || quantity == diagramName(d)) shown.push_back(d);
  return shown;
}

bool writeOverlay(const std::filesystem::path& dir, const std::vector<OverlaidRun>& runs,
                  const std::vector<Diagram>& shown, const OutputUnits& units) {
  std::vector<CsvTable> tables;
  tables.reserve(runs.size());  // FieldSeries point into it
  std::vector<FieldSeries> series;
  std::string caption = "overlay:";
  std::vector<const Model*> models;
  for (const OverlaidRun& r : runs) {
    tables.push_back(overlaidTable(r, units));
    const std::string& file = tables.back().title();
    tables.back().write(dir / file);
    series.push_back({&tables.back(), file, r.label});
    models.push_back(r.run->model.get());
    caption += (&r == &runs.front() ? " " : ", ") + r.label + " (" +
               overlaidAnalysis(*r.run)->name + ")";
  }
  return drawChart(
      dir, staticDiagrams(caption, "overlay", series, commonPointMarkers(models), shown, units));
}

}  // namespace beamrotor

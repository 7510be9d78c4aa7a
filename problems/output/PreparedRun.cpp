// Preparing a run for writing (see PreparedRun.hpp).
#include "problems/output/PreparedRun.hpp"

#include "problems/output/crank/CrankOutput.hpp"
#include "problems/output/files/FileNames.hpp"
#include "problems/output/files/FiniteCheck.hpp"
#include "problems/output/structure/MemberOutput.hpp"
#include "problems/output/structure/StabilityOutput.hpp"
#include "problems/output/structure/Tables.hpp"
#include "problems/output/transient/TransientFiles.hpp"

namespace beamrotor {

std::vector<std::pair<std::string, const CsvTable*>> PreparedAnalysis::tables() const {
  std::vector<std::pair<std::string, const CsvTable*>> all;
  for (const std::optional<CsvTable>* t : {&fields, &modes, &shapes, &history})
    if (*t) all.emplace_back((*t)->title(), &**t);
  if (rotor)
    for (const std::optional<CsvTable>* t :
         {&rotor->modes, &rotor->campbell, &rotor->critical, &rotor->unbalance, &rotor->api684,
          &rotor->frf, &rotor->bearings})
      if (*t) all.emplace_back((*t)->title(), &**t);
  for (const std::vector<CsvTable>* list : {&members, &envelopes, &crank})
    for (const CsvTable& t : *list) all.emplace_back(t.title(), &t);
  return all;
}

namespace {

/// Each case's VTK samples and, for a frame with combinations, the envelope along every member.
void prepareCases(const AnalysisOutcome& a, PreparedAnalysis& p) {
  for (std::size_t i = 0; i < a.cases.size(); ++i) {
    const CaseOutcome& c = a.cases[i];
    const NodalField& u = c.statics.displacement;
    p.cases.push_back({&c, caseVtu(p.stem, int(i) + 1), sampleStatics(*c.model, u),
                       elementPeaks(*c.model, u)});
  }
  std::vector<LoadedSolution> combinations;
  std::vector<std::string> names;
  for (const CaseOutcome& c : a.cases)
    if (c.combination) {
      combinations.push_back({c.model.get(), &c.statics.displacement});
      names.push_back(c.name);
    }
  if (combinations.empty()) return;
  for (const auto& [name, elements] : combinations.front().model->members())
    p.envelopes.push_back(memberEnvelopeTable(
        envelopeCsv(p.stem, name), memberEnvelope(combinations, elements, kIntervalsPerElement),
        names));
}

}  // namespace

PreparedRun prepareRun(const RunResult& run) {
  // 1. Refuse non-finite numbers and analyses that would overwrite each other's files.
  requireFinite(run);
  requireDistinctFileStems(run.analyses);
  const Model& model = *run.model;

  // 2. Sample the statics along the line and build every table.
  PreparedRun prepared{&run, {}, {}};
  std::vector<std::vector<ElementPeaks>> peaks;
  for (const AnalysisOutcome& a : run.analyses) {
    PreparedAnalysis p{&a, fileStem(a.name), {}, {}, {}, {}, {}, {}, {}, {}, {}, {}, {}};
    if (a.transient) p.history = historyTable(historyCsv(p.stem), *a.transient);
    if (a.statics) {
      p.stations = sampleStatics(model, a.statics->displacement);
      p.peaks = elementPeaks(model, a.statics->displacement);
      p.fields = staticFieldsTable(fieldsCsv(p.stem), p.stations);
      for (const auto& [name, elements] : model.members())
        p.members.push_back(memberTable(memberCsv(p.stem, name), model, elements, p.stations));
      prepareCases(a, p);
    }
    if (a.modal) {
      p.modes = modesTable(modesCsv(p.stem), *a.modal);
      p.shapes = modeShapesTable(shapesCsv(p.stem), model, *a.modal);
    }
    if (a.buckling) {
      p.modes = bucklingFactorsTable(bucklingFactorsCsv(p.stem), *a.buckling);
      p.shapes = modeShapesTable(shapesCsv(p.stem), model, bucklingShapes(*a.buckling));
    }
    if (a.rotor) p.rotor = prepareRotor(a, p.stem);
    if (a.crank) p.crank = crankTables(*a.crank, p.stem);
    peaks.push_back(p.peaks);
    prepared.analyses.push_back(std::move(p));
  }

  // 3. results.json, with derived numbers (largest stress, ratios) checked as well.
  prepared.doc = runJson(run, peaks);
  requireFiniteNumbers(prepared.doc, kResultsJson);
  return prepared;
}

}  // namespace beamrotor

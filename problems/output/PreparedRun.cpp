// Preparing a run for writing (see PreparedRun.hpp).
#include "problems/output/PreparedRun.hpp"

#include <map>
#include <variant>

#include "problems/output/crank/CrankOutput.hpp"
#include "problems/output/moving/MovingOutput.hpp"
#include "problems/output/torsion/TorsionOutput.hpp"
#include "problems/output/files/FileNames.hpp"
#include "problems/output/rotor/RotorFileNames.hpp"
#include "problems/output/rotor/RotorOrbitChart.hpp"
#include "problems/output/files/FileWriting.hpp"
#include "problems/output/files/FiniteCheck.hpp"
#include "problems/output/files/TableUnits.hpp"
#include "problems/output/structure/MemberOutput.hpp"
#include "problems/output/structure/StabilityOutput.hpp"
#include "problems/output/structure/Tables.hpp"
#include "problems/output/structure/ThinnedStations.hpp"
#include "problems/output/transient/TransientFiles.hpp"
#include "problems/run/Overloaded.hpp"
#include "problems/output/structure/BaseMotionOutput.hpp"
#include "problems/output/structure/SpectrumOutput.hpp"

namespace beamrotor {

std::vector<std::pair<std::string, const CsvTable*>> PreparedAnalysis::tables() const {
  std::vector<std::pair<std::string, const CsvTable*>> all;
  for (const std::optional<CsvTable>* t :
       {&fields, &reactions, &springs, &modes, &shapes, &history, &baseMotion})
    if (*t) all.emplace_back((*t)->title(), &**t);
  if (caseTable) all.emplace_back(caseTable->title(), &*caseTable);
  if (rotor)
    for (const std::optional<CsvTable>* t :
         {&rotor->modes, &rotor->orbits, &rotor->campbell, &rotor->critical, &rotor->unbalance,
          &rotor->api684, &rotor->frf, &rotor->bearings, &rotor->map, &rotor->mapBearings,
          &rotor->mapCrossings, &rotor->bearingLoads, &rotor->sag, &rotor->levelOne,
          &rotor->runUp, &rotor->runUpHistory})
      if (*t) all.emplace_back((*t)->title(), &**t);
  for (const std::vector<CsvTable>* list :
       {&members, &envelopes, &crank, &torsion, &moving, &spectrum})
    for (const CsvTable& t : *list) all.emplace_back(t.title(), &t);
  return all;
}

const PreparedCase* PreparedAnalysis::caseAt(int index) const {
  for (const PreparedCase& c : cases)
    if (c.index == index) return &c;
  return nullptr;
}

namespace {

/// The dimension of a load case's value: a reaction or a spring's force (fx .. mz), a point's
/// displacement (ux .. rz) or a member's resultant extreme ("Mz max").
Dimension caseValueDimension(const std::string& quantity, const std::string& component) {
  const char first = component.empty() ? ' ' : component.front();
  if (quantity == "displacement") return first == 'r' ? dim::angle : dim::length;
  if (quantity == "member") {
    if (component.rfind("deflection", 0) == 0) return dim::length;
    return first == 'T' || first == 'M' ? dim::moment : dim::force;
  }
  return first == 'm' ? dim::moment : dim::force;
}

/// The load cases' table (<stem>_cases.csv): every value of a static analysis' load cases and
/// combinations, one a row (case, combination, quantity, at, component, value, unit), read
/// from their results.json entries so that the table and the document never disagree. Its
/// columns, without rows.
CsvTable emptyLoadCasesTable(const std::string& file) {
  return CsvTable(file, {{"case", ""}, {"combination", ""}, {"quantity", ""}, {"at", ""},
                         {"component", ""}, {"value", ""}, {"unit", ""}});
}

/// Adds the rows of one case's results.json entry (CaseEntries::entry), in the table's order:
/// reactions, spring and bearing forces, point displacements and member resultant extremes,
/// each value in `units` (SI where none is set) with its unit.
void addLoadCaseRows(CsvTable& table, const Json& entry, const OutputUnits& units) {
  const std::string name = entry.at("name").get<std::string>();
  const long long combination = entry.at("combination").get<bool>() ? 1 : 0;
  const auto add = [&](const char* quantity, const std::string& at, const std::string& component,
                       double si) {
    const OutputUnits::Shown shown = units.ofSI(caseValueDimension(quantity, component));
    table.addRow(
        {name, combination, std::string(quantity), at, component, si * shown.factor, shown.unit});
  };
  for (const auto& [key, quantity] : {std::pair{"reactions", "reaction"},
                                      std::pair{"springs", "spring"},
                                      std::pair{"displacements", "displacement"}})
    if (entry.contains(key))
      for (const auto& where : entry.at(key).items())
        for (const auto& component : where.value().items())
          add(quantity, where.key(), component.key(), component.value().get<double>());
  if (!entry.contains("members")) return;
  for (const auto& member : entry.at("members").items())
    for (const auto& component : member.value().items()) {
      const Json& v = component.value();
      if (!v.is_object() || !v.contains("max") || !v.at("max").is_object()) continue;
      for (const char* extreme : {"max", "min"})
        add("member", member.key(), component.key() + " " + extreme,
            v.at(extreme).at("value").get<double>());
    }
}

/// The envelope over the combinations, the samples of the cases written (writtenCases) and,
/// for a frame with combinations, the tables of the envelope along every member (computed
/// with the extremes: runExtremes, MemberEnvelopes::computed).
void prepareCases(const Model& model, const AnalysisOutcome& a, PreparedAnalysis& p, bool planar,
                  bool allCases) {
  const std::vector<CaseOutcome>& cases = casesOf(a);
  if (cases.empty()) return;
  p.envelope = caseEnvelope(model, cases, p.extremes->cases, p.extremes->canGovern);
  const bool chords = caseChordDeflections(model, cases.size());
  SolutionPolynomials summed;
  for (int i : writtenCases(*p.envelope, cases.size(), planar, allCases)) {
    const StaticExtremes& x = p.extremes->cases.at(i);
    p.cases.push_back({&cases[i], i, caseVtu(p.stem, i + 1), sampleStatics(cases[i].on(model)), &x,
                       elementPeaks(cases[i].on(model)), std::nullopt});
    // The same computation as runExtremes', places kept: the same values (where it kept the
    // values alone or, for a combination that cannot govern, none).
    if (x.ranges.empty() && !model.members().empty())
      p.cases.back().placed = caseExtremes(model, cases[i], summed, chords, RangesKept::withPlaces);
  }
  std::vector<std::string> names;
  for (const CaseOutcome& c : casesOf(a))
    if (c.combination) names.push_back(c.name);
  if (names.empty()) return;
  if (oneMembersTable(model)) {
    p.envelopes.push_back(
        membersEnvelopeTable(envelopesCsv(p.stem), model, p.envelopeStations, names));
    return;
  }
  for (std::size_t m = 0; m < model.members().size(); ++m)
    p.envelopes.push_back(memberEnvelopeTable(envelopeCsv(p.stem, model.members()[m].first),
                                              p.envelopeStations[m], names));
}

/// A static analysis sampled along the line, its fields and member tables, and its cases.
void prepareStatic(const Model& model, const AnalysisOutcome& a, const StaticResult& statics,
                   PreparedAnalysis& p, const OutputChoices& choices, bool planar) {
  p.stations = sampleStatics({model, statics.displacement});
  p.fields = staticFieldsTable(fieldsCsv(p.stem),
                               choices.fullTables ? p.stations : thinnedStations(p.stations));
  if (!statics.reactions.empty())
    p.reactions = reactionsTable(reactionsCsv(p.stem), model, statics);
  if (!statics.elementForces.empty())
    p.springs = springForcesTable(springsCsv(p.stem), model, statics);
  const StationsByElement byElement(p.stations, model.elements().size());
  if (oneMembersTable(model))
    p.members.push_back(membersTable(membersCsv(p.stem), model, byElement));
  else
    for (const auto& [name, elements] : model.members())
      p.members.push_back(memberTable(memberCsv(p.stem, name), model, elements, byElement));
  prepareCases(model, a, p, planar, choices.allCases);
}

/// Refuses non-finite numbers and analyses that would overwrite each other's files.
void requireWritable(const RunResult& run) {
  requireFinite(run);
  requireDistinctFileStems(run.analyses);
}

/// results.json of run from its extremes, with derived numbers (largest stress, ratios)
/// checked for NaN and infinity as well; the cases' entries are checked as they are made.
ResultsDocument checkedDocument(const RunResult& run,
                                const std::vector<AnalysisExtremes>& extremes) {
  ResultsDocument results = runDocument(run, extremes);
  requireFiniteNumbers(results.doc, kResultsJson);
  return results;
}

/// Every table of p in `units` (inUnits).
void showInUnits(PreparedAnalysis& p, const OutputUnits& units) {
  for (std::optional<CsvTable>* t :
       {&p.fields, &p.springs, &p.reactions, &p.modes, &p.shapes, &p.history, &p.baseMotion})
    if (*t) *t = inUnits(std::move(**t), units);
  if (p.rotor)
    for (std::optional<CsvTable>* t :
         {&p.rotor->modes, &p.rotor->orbits, &p.rotor->campbell, &p.rotor->critical,
          &p.rotor->unbalance, &p.rotor->api684, &p.rotor->frf, &p.rotor->bearings, &p.rotor->map,
          &p.rotor->mapBearings, &p.rotor->mapCrossings, &p.rotor->bearingLoads, &p.rotor->sag,
          &p.rotor->runUp, &p.rotor->runUpHistory, &p.rotor->levelOne})
      if (*t) *t = inUnits(std::move(**t), units);
  for (std::vector<CsvTable>* list :
       {&p.members, &p.envelopes, &p.crank, &p.torsion, &p.moving, &p.spectrum})
    for (CsvTable& t : *list) t = inUnits(std::move(t), units);
}

}  // namespace

Json prepareRunDocument(const RunResult& run) {
  requireWritable(run);
  Json doc = runJson(run, runExtremes(run));
  requireFiniteNumbers(doc, kResultsJson);
  return doc;
}

Json wholeResults(PreparedRun& prepared) {
  Json doc = prepared.results.complete();
  requireFiniteNumbers(doc, kResultsJson);
  for (const CaseEntries& c : prepared.results.cases) {
    PreparedAnalysis& p = prepared.analyses.at(c.analysis());
    p.caseTable = emptyLoadCasesTable(casesCsv(p.stem));
    for (const Json& entry : doc.at("analyses").at(c.analysis()).at("cases"))
      addLoadCaseRows(*p.caseTable, entry, prepared.units);
  }
  return doc;
}

void writeResultsAndCaseTables(const PreparedRun& prepared, const std::filesystem::path& dir) {
  // Each analysis' load cases' table is open while results.json is written and takes each
  // case's rows as its entry goes by: a table of that case alone.
  std::map<std::size_t, OutputFile> tables;  // by analysis
  for (const CaseEntries& c : prepared.results.cases) {
    const std::string file = casesCsv(prepared.analyses.at(c.analysis()).stem);
    emptyLoadCasesTable(file).writeColumnsTo(
        tables.try_emplace(c.analysis(), dir / file).first->second.stream());
  }
  prepared.results.write(dir / kResultsJson, [&](const CaseEntries& c, const Json& entry) {
    CsvTable rows = emptyLoadCasesTable(casesCsv(prepared.analyses.at(c.analysis()).stem));
    addLoadCaseRows(rows, entry, prepared.units);
    rows.writeRowsTo(tables.at(c.analysis()).stream());
  });
  for (auto& [analysis, table] : tables) table.finish();
}

PreparedRun prepareRun(const RunResult& run, const OutputChoices& choices) {
  const OutputUnits& units = choices.units;
  // 1. Refuse non-finite numbers and analyses that would overwrite each other's files.
  requireWritable(run);
  const Model& model = *run.model;
  const bool planar = run.dimension == "planar";

  // 2. The extremes of every static solution, then the samples along the line and every table.
  PreparedRun prepared{&run, runExtremes(run, MemberEnvelopes::computed), {}, {}, units};
  for (std::size_t i = 0; i < run.analyses.size(); ++i) {
    const AnalysisOutcome& a = run.analyses[i];
    PreparedAnalysis p;
    p.outcome = &a;
    p.stem = fileStem(a.name);
    p.envelopeStations = std::move(prepared.extremes[i].memberEnvelopes);
    p.extremes = &prepared.extremes[i];
    std::visit(
        Overloaded{
            [&](const StaticOutcome& r) {
              prepareStatic(model, a, r.statics, p, choices, planar);
            },
            [&](const SecondOrderResult& r) {
              prepareStatic(model, a, r.secondOrder, p, choices, planar);
            },
            [&](const ModalResult& r) {
              p.modes = modesTable(modesCsv(p.stem), r);
              p.shapes = modeShapesTable(shapesCsv(p.stem), model, r);
            },
            [&](const TorsionOutcome& r) {
              p.modes = modesTable(modesCsv(p.stem), r.modes);
              p.shapes = modeShapesTable(shapesCsv(p.stem), *r.model, r.modes);
              p.torsion = torsionTables(r, p.stem, choices.units);
            },
            [&](const BucklingResult& r) {
              p.modes = bucklingFactorsTable(bucklingFactorsCsv(p.stem), r);
              p.shapes = modeShapesTable(shapesCsv(p.stem), model, bucklingShapes(model, r));
            },
            [&](const TransientOutcome& r) { p.history = historyTable(historyCsv(p.stem), r); },
            [&](const RotorModesResult& r) {
              p.rotor = prepareRotor(r, p.stem);
              p.rotor->orbits = modeOrbitsTable(orbitsCsv(p.stem), r, model);
            },
            [&](const RotorResult auto& r) { p.rotor = prepareRotor(r, p.stem); },
            [&](const CrankSliderOutcome& r) { p.crank = crankTables(r, p.stem); },
            [&](const MovingLoadOutcome& r) { p.moving = movingTables(r, p.stem, choices.units); },
            [&](const ResponseSpectrumResult& r) {
              p.modes = modesTable(modesCsv(p.stem), r.modal);
              p.shapes = modeShapesTable(shapesCsv(p.stem), model, r.modal);
              p.spectrum = spectrumTables(r, model, p.stem, choices.units);
            },
            [&](const BaseMotionResult& r) { p.baseMotion = baseMotionTable(r, model, p.stem); }},
        a.result);
    prepared.analyses.push_back(std::move(p));
  }

  // 3. results.json, its cases' entries left to be made as written, with the VTK files of the
  //    cases written.
  prepared.results = checkedDocument(run, prepared.extremes);
  for (CaseEntries& entries : prepared.results.cases)
    for (const PreparedCase& c : prepared.analyses.at(entries.analysis()).cases)
      entries.nameVtu(std::size_t(c.index), c.vtu);
  // 4. Every table in the user's units; results.json stays SI.
  for (PreparedAnalysis& p : prepared.analyses) showInUnits(p, units);
  return prepared;
}

}  // namespace beamrotor

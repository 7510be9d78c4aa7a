// Ties the writers together. Each run is first prepared in memory (checked for NaN and
// infinity, sampled along the line, its JSON and tables built), so that every error a result
// can cause is raised before the first byte is written; then the files are written into a
// temporary directory that replaces the output directory only when complete.
#include "problems/output/Output.hpp"

#include <optional>
#include <string>
#include <stdexcept>
#include <variant>

#include "problems/deck/parse/Suggest.hpp"
#include "problems/output/files/AtomicDirectory.hpp"
#include "problems/output/structure/Charts.hpp"
#include "problems/output/crank/CrankOutput.hpp"
#include "problems/output/files/CsvTable.hpp"
#include "problems/output/structure/CaseEnvelope.hpp"
#include "problems/output/structure/EnvelopeCharts.hpp"
#include "problems/output/files/FileNames.hpp"
#include "problems/output/files/FiniteCheck.hpp"
#include "problems/output/structure/FrameCharts.hpp"
#include "problems/output/JsonWriter.hpp"
#include "problems/output/structure/LineSampling.hpp"
#include "problems/output/structure/OverlaidDiagrams.hpp"
#include "problems/output/PreparedRun.hpp"
#include "problems/output/rotor/RotorOutput.hpp"
#include "problems/output/structure/StabilityOutput.hpp"
#include "problems/output/SweepTable.hpp"
#include "problems/output/structure/Tables.hpp"
#include "problems/output/transient/TransientFiles.hpp"
#include "problems/output/structure/VtkWriter.hpp"
#include "problems/run/Overloaded.hpp"

namespace beamrotor {

namespace {

namespace fs = std::filesystem;

/// "pump_rod: static (eta = 0.4, w0 = 0.001 in SI units)": the caption of a run's charts; `what` follows
/// the analysis' name, and the parameter `left` out is not listed. A long caption puts the
/// parameters on lines of their own ('\n'), so that the chart's width holds them.
std::string caption(const RunResult& run, const std::string& analysis, const std::string& what = "",
                    const std::string& left = "") {
  constexpr std::size_t kLine = 90;  // characters across a 900-pixel chart at its title font
  const std::string head = (run.deckName.empty() ? "" : run.deckName + ": ") + analysis + what;
  std::vector<std::string> items;
  for (const auto& [name, value] : run.parameters)
    if (name != left) items.push_back(name + " = " + exactDecimal(value));
  // A deck's bare numbers are SI (FORMAT.md): say so, since a parameter has no unit of its own.
  if (!items.empty()) items.back() += " in SI units";
  std::string oneLine = head;
  for (std::size_t i = 0; i < items.size(); ++i)
    oneLine += (i ? ", " : " (") + items[i] + (i + 1 == items.size() ? ")" : "");
  if (oneLine.size() <= kLine) return oneLine;
  std::string text = head, line;
  for (std::size_t i = 0; i < items.size(); ++i) {
    const std::string item = items[i] + (i + 1 == items.size() ? "" : ",");
    if (!line.empty() && line.size() + 1 + item.size() > kLine) text += "\n" + line, line.clear();
    line += (line.empty() ? "" : " ") + item;
  }
  return line.empty() ? text : text + "\n" + line;
}

/// The load cases and combinations of a static analysis's results.json entry as one table:
/// reactions, point displacements and member resultant extremes, one value per row.
CsvTable loadCasesTable(const Json& analysis, const std::string& file) {
  CsvTable t(file, {{"case", ""}, {"combination", ""}, {"quantity", ""}, {"at", ""},
                    {"component", ""}, {"value", ""}});
  for (const Json& c : analysis.at("cases")) {
    const std::string name = c.at("name").get<std::string>();
    const long long combination = c.at("combination").get<bool>() ? 1 : 0;
    for (const char* key : {"reactions", "displacements"})
      for (const auto& where : c.at(key).items())
        for (const auto& component : where.value().items())
          t.addRow({name, combination, std::string(key == std::string("reactions")
                                                        ? "reaction" : "displacement"),
                    where.key(), component.key(), component.value().get<double>()});
    if (!c.contains("members")) continue;
    for (const auto& member : c.at("members").items())
      for (const auto& component : member.value().items()) {
        const Json& v = component.value();
        if (!v.is_object() || !v.contains("max") || !v.at("max").is_object()) continue;
        for (const char* extreme : {"max", "min"})
          t.addRow({name, combination, std::string("member"), member.key(),
                    component.key() + " " + extreme, v.at(extreme).at("value").get<double>()});
      }
  }
  return t;
}

/// A frame's charts: the whole structure at once, not a line coordinate through its members.
/// The deformed shape and moments under the deck's own loads (unless only its load cases load
/// it), under each combination that governs an extreme (governingCombinations), the envelope
/// of the moments on the frame, and up to kEnvelopeChartsUpTo members' own envelope charts.
void drawFrameCharts(const PreparedRun& prepared, const PreparedAnalysis& p, const fs::path& dir) {
  const RunResult& run = *prepared.run;
  const Model& model = *run.model;
  const AnalysisOutcome& a = *p.outcome;
  const bool planar = run.dimension == "planar";
  const auto draw = [&](const std::vector<StaticStation>& stations, const StaticExtremes& x,
                        const std::string& what, const std::string& chart) {
    const StationsByElement byElement(stations, model.elements().size());
    const FrameDrawing frame{&model, &byElement, &x.ranges, x.largestDisplacement.value};
    drawChart(dir, frameChart(caption(run, a.name, what), chart, frame, planar));
  };
  const StaticOutcome* statics = resultOf<StaticOutcome>(a);
  if (!statics || statics->ownLoads || p.cases.empty())
    draw(p.stations, *p.extremes->own, "", frameShapeChart(p.stem));
  if (p.envelopeStations.empty()) return;
  const std::vector<CaseOutcome>& cases = casesOf(a);
  const CaseEnvelope envelope = caseEnvelope(model, cases, p.extremes->cases);
  for (int k : governingCombinations(envelope, planar))
    draw(p.cases.at(k).stations, p.extremes->cases.at(k), ", combination " + cases[k].name,
         caseFrameChart(p.stem, k + 1));
  std::vector<std::string> names;
  for (const CaseOutcome& c : cases)
    if (c.combination) names.push_back(c.name);
  drawChart(dir, frameEnvelopeChart(caption(run, a.name, ", envelope of the combinations"),
                                    frameEnvelopeChart(p.stem), model, p.envelopeStations, names,
                                    planar));
  if (model.members().size() > kEnvelopeChartsUpTo) return;
  for (std::size_t m = 0; m < p.envelopes.size(); ++m) {
    const std::string& member = model.members()[m].first;
    drawChart(dir, memberEnvelopeChart(caption(run, a.name, ", envelope of " + member),
                                       envelopeChart(p.stem, member), p.envelopes[m],
                                       p.envelopes[m].title()));
  }
}

/// A static analysis' files: its fields, members, load cases, VTK and diagrams.
void writeStaticFiles(const PreparedRun& prepared, const PreparedAnalysis& p,
                      const StaticResult& statics, const fs::path& dir, bool charts) {
  const RunResult& run = *prepared.run;
  const Model& model = *run.model;
  const AnalysisOutcome& a = *p.outcome;
  p.fields->write(dir / fieldsCsv(p.stem));
  if (!casesOf(a).empty())
    for (const Json& entry : prepared.doc.at("analyses"))
      if (entry.at("name") == a.name && entry.contains("cases"))
        loadCasesTable(entry, casesCsv(p.stem)).write(dir / casesCsv(p.stem));
  for (const std::vector<CsvTable>* list : {&p.members, &p.envelopes})
    for (const CsvTable& table : *list) table.write(dir / table.title());
  writeStaticVtu(dir / staticVtu(p.stem), {model, statics.displacement}, p.stations,
                 p.extremes->own->peaks);
  if (!p.cases.empty()) {
    std::vector<PvdEntry> entries;
    for (const PreparedCase& c : p.cases) {
      writeStaticVtu(dir / c.vtu, c.outcome->on(model), c.stations, c.extremes->peaks);
      entries.push_back({double(entries.size() + 1), c.vtu});
    }
    writePvd(dir / casesPvd(p.stem), entries);
  }
  if (charts && !p.stations.empty() && p.members.empty())
    drawChart(dir, staticDiagrams(caption(run, a.name), diagramsChart(p.stem),
                                  {{&*p.fields, fieldsCsv(p.stem), ""}}, namedPointMarkers(model)));
  if (charts && !p.members.empty()) drawFrameCharts(prepared, p, dir);
}

/// A modal analysis' files: its frequencies, shapes, one VTK file per mode and the chart.
void writeModalFiles(const RunResult& run, const PreparedAnalysis& p, const Model& model,
                     const ModalResult& modal, const fs::path& dir, bool charts) {
  p.modes->write(dir / modesCsv(p.stem));
  p.shapes->write(dir / shapesCsv(p.stem));
  std::vector<PvdEntry> entries;
  for (std::size_t m = 0; m < modal.modes.size(); ++m) {
    const int number = int(m) + 1;
    writeModeVtu(dir / modeVtu(p.stem, number), model, modal.modes[m], number);
    // Mode numbers as time steps: rigid-body modes share frequency 0, numbers never tie.
    entries.push_back({double(number), modeVtu(p.stem, number)});
  }
  writePvd(dir / collectionPvd(p.stem), entries);
  if (charts && p.shapes->rowCount() > 0)
    drawChart(dir, modeShapesChart(caption(run, p.outcome->name), shapesChart(p.stem), model, modal,
                                   *p.shapes, shapesCsv(p.stem)));
}

void writeRunFiles(const PreparedRun& prepared, const fs::path& dir, bool charts) {
  const RunResult& run = *prepared.run;
  const Model& model = *run.model;
  writeJson(prepared.doc, dir / kResultsJson);
  for (const PreparedAnalysis& p : prepared.analyses) {
    const AnalysisOutcome& a = *p.outcome;
    std::visit(
        Overloaded{
            [&](const StaticOutcome& r) { writeStaticFiles(prepared, p, r.statics, dir, charts); },
            [&](const SecondOrderResult& r) {
              writeStaticFiles(prepared, p, r.secondOrder, dir, charts);
            },
            [&](const BucklingResult&) {
              writeBucklingFiles(p, model, dir, caption(run, a.name), charts);
            },
            [&](const ModalResult& r) { writeModalFiles(run, p, model, r, dir, charts); },
            [&](const TorsionOutcome& r) {
              writeModalFiles(run, p, *r.model, r.modes, dir, charts);
            },
            [&](const TransientOutcome& r) {
              writeTransientFiles(dir, model, p.stem, r, *p.history,
                                  charts ? caption(run, a.name) : "");
            },
            [&](const RotorResult auto& r) {
              writeRotorFiles({*p.rotor, p.stem, model, dir, caption(run, a.name), charts}, r);
            },
            [&](const CrankSliderOutcome& r) {
              for (const CsvTable& table : p.crank) table.write(dir / table.title());
              if (charts) drawCrankCharts(dir, r, p.stem, caption(run, a.name));
            }},
        a.result);
  }
}

}  // namespace

void writeRunOutputs(const RunResult& run, const fs::path& dir, const AlsoWrite& also) {
  writePreparedRun(prepareRun(run), dir, also);
}

void writePreparedRun(const PreparedRun& prepared, const fs::path& dir, const AlsoWrite& also) {
  writeDirectoryAtomically(dir, [&](const fs::path& temporary) {
    writeRunFiles(prepared, temporary, /*charts=*/true);
    if (also) also(temporary);
  });
}

void writeSweepOutputs(const SweepResult& sweep, const fs::path& dir, const AlsoWrite& also) {
  // 1. Prepare every value and the sweep's own tables before writing anything.
  if (sweep.values.empty()) throw std::invalid_argument("a sweep needs at least one value");
  if (sweep.runs.size() != sweep.values.size())
    throw std::invalid_argument("sweep over '" + sweep.parameter + "' has " +
                                std::to_string(sweep.values.size()) + " values but " +
                                std::to_string(sweep.runs.size()) + " runs");
  std::vector<PreparedRun> prepared;
  std::vector<Json> docs;
  std::vector<std::string> directories;
  for (std::size_t i = 0; i < sweep.runs.size(); ++i) {
    prepared.push_back(prepareRun(sweep.runs[i]));
    docs.push_back(prepared.back().doc);
    directories.push_back(sweepValueDirectory(i, sweep.runs.size()));
  }
  const Json sweepDoc = sweepJson(sweep, docs, directories);
  requireFiniteNumbers(sweepDoc, kSweepJson);
  const std::vector<SweepQuantity> quantities = sweepQuantities(docs);
  const CsvTable table = sweepTable(kSweepCsv, sweep, docs, quantities);

  // 2. Per value its own results (no charts: they would dominate the time of a long sweep),
  // then the sweep's JSON, CSV, a .pvd series per static analysis, and the sweep charts.
  writeDirectoryAtomically(dir, [&](const fs::path& temporary) {
    for (std::size_t i = 0; i < prepared.size(); ++i) {
      fs::create_directory(temporary / directories[i]);
      writeRunFiles(prepared[i], temporary / directories[i], /*charts=*/false);
    }
    writeJson(sweepDoc, temporary / kSweepJson);
    table.write(temporary / kSweepCsv);
    const RunResult& first = sweep.runs.front();
    for (std::size_t k = 0; k < first.analyses.size(); ++k) {
      const AnalysisOutcome& a = first.analyses[k];
      const std::string stem = fileStem(a.name);
      if (staticsOf(a)) {
        std::vector<PvdEntry> series;
        for (std::size_t i = 0; i < sweep.values.size(); ++i)
          series.push_back({sweep.values[i], directories[i] + "/" + staticVtu(stem)});
        writePvd(temporary / collectionPvd(stem), series);
        std::vector<const CsvTable*> fields;
        std::vector<std::string> files, values;
        for (std::size_t i = 0; i < prepared.size(); ++i) {
          fields.push_back(&*prepared[i].analyses[k].fields);
          files.push_back(directories[i] + "/" + fieldsCsv(stem));
          values.push_back(exactDecimal(sweep.values[i]));
        }
        // Diagrams along a line; a frame's members are in its own files per value.
        if (!prepared.front().analyses[k].stations.empty() &&
            prepared.front().analyses[k].members.empty())
          drawOverlaidDiagrams(
              temporary,
              caption(first, a.name, " at " + sweep.parameter + " = " + joinNames(values),
                      sweep.parameter),
              diagramsChart(stem), sweep, fields, files);
      }
      std::vector<SweepQuantity> own;
      for (const SweepQuantity& q : quantities)
        if (q.analysis == a.name) own.push_back(q);
      if (!own.empty())
        drawChart(temporary, sweepChart(first.deckName + ": " + a.name + " over " + sweep.parameter,
                                        sweepChart(stem), sweep.parameter, sweep.unit, own, table,
                                        kSweepCsv));
    }
    if (also) also(temporary);
  });
}

}  // namespace beamrotor

// Ties the writers together. Each run is first prepared in memory (checked for NaN and
// infinity, sampled along the line, its JSON and tables built), so that nearly every error a
// result can cause is raised before the first byte is written; then the files are written into
// a temporary directory that replaces the output directory only when complete (so that a NaN
// found in a load case's entry as it is written, or an interruption, leaves the old one).
#include "problems/output/Output.hpp"

#include <cstdio>
#include <optional>
#include <string>
#include <stdexcept>
#include <variant>

#include "fem/assembly/ParallelParts.hpp"
#include "problems/deck/parse/Suggest.hpp"
#include "problems/output/ChartCaption.hpp"
#include "problems/output/files/AtomicDirectory.hpp"
#include "problems/output/files/ChartBatch.hpp"
#include "problems/output/files/ChartParts.hpp"
#include "problems/output/structure/Charts.hpp"
#include "problems/output/crank/CrankOutput.hpp"
#include "problems/output/moving/MovingOutput.hpp"
#include "problems/output/moving/MovingVtk.hpp"
#include "problems/output/torsion/TorsionOutput.hpp"
#include "problems/output/files/CsvTable.hpp"
#include "problems/output/structure/CaseEnvelope.hpp"
#include "problems/output/structure/EnvelopeCharts.hpp"
#include "problems/output/files/FileNames.hpp"
#include "problems/output/files/FiniteCheck.hpp"
#include "problems/output/files/TableUnits.hpp"
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
#include "problems/output/structure/BaseMotionVtk.hpp"
#include "problems/output/structure/VtkWriter.hpp"
#include "problems/run/Overloaded.hpp"
#include "problems/output/structure/BaseMotionOutput.hpp"
#include "problems/output/structure/SpectrumOutput.hpp"

namespace beamrotor {

namespace {

namespace fs = std::filesystem;

/// The caption of a chart of prepared's run (ChartCaption.hpp), in prepared's units.
std::string captionOf(const PreparedRun& prepared, const std::string& analysis,
                      const std::string& what = "") {
  return chartCaption(*prepared.run, analysis, what, "", prepared.units);
}

/// A frame's charts: the whole structure at once, not a line coordinate through its members.
/// The deformed shape and moments under the deck's own loads (unless only its load cases load
/// it), under each combination that governs an extreme (governingCombinations), the envelope
/// of the moments on the frame, and up to kEnvelopeChartsUpTo members' own envelope charts.
void drawFrameCharts(const PreparedRun& prepared, const PreparedAnalysis& p,
                     const StaticResult& solution, const fs::path& dir) {
  const RunResult& run = *prepared.run;
  const Model& model = *run.model;
  const AnalysisOutcome& a = *p.outcome;
  const bool planar = run.dimension == "planar";
  const auto draw = [&](const std::vector<StaticStation>& stations, const StaticExtremes& x,
                        const NodalField& u, const std::string& what, const std::string& chart) {
    const StationsByElement byElement(stations, model.elements().size());
    const FrameDrawing frame{&model, &byElement, &x.ranges, x.largestDisplacement.value, &u};
    drawChart(dir,
              frameChart(captionOf(prepared, a.name, what), chart, frame, planar, prepared.units));
  };
  const StaticOutcome* statics = resultOf<StaticOutcome>(a);
  if (!statics || statics->ownLoads || p.cases.empty())
    draw(p.stations, *p.extremes->own, solution.displacement, "", frameShapeChart(p.stem));
  if (p.envelopeStations.empty()) return;
  const std::vector<CaseOutcome>& cases = casesOf(a);
  for (int k : governingCombinations(*p.envelope, planar))
    draw(p.caseAt(k)->stations, p.caseAt(k)->withPlaces(), p.caseAt(k)->outcome->statics.displacement,
         ", combination " + cases[k].name,
         caseFrameChart(p.stem, k + 1));
  std::vector<std::string> names;
  for (const CaseOutcome& c : cases)
    if (c.combination) names.push_back(c.name);
  drawChart(dir, frameEnvelopeChart(captionOf(prepared, a.name, ", envelope of the combinations"),
                                    frameEnvelopeChart(p.stem), model, p.envelopeStations, names,
                                    planar, prepared.units));
  if (model.members().size() > kEnvelopeChartsUpTo) return;
  for (std::size_t m = 0; m < p.envelopes.size(); ++m) {
    const std::string& member = model.members()[m].first;
    drawChart(dir, memberEnvelopeChart(captionOf(prepared, a.name, ", envelope of " + member),
                                       envelopeChart(p.stem, member), p.envelopes[m],
                                       p.envelopes[m].title(), prepared.units));
  }
}

/// A static analysis' files: its fields, members, load cases, VTK and diagrams.
void writeStaticFiles(const PreparedRun& prepared, const PreparedAnalysis& p,
                      const StaticResult& statics, const fs::path& dir, bool charts) {
  const RunResult& run = *prepared.run;
  const Model& model = *run.model;
  const AnalysisOutcome& a = *p.outcome;
  p.fields->write(dir / fieldsCsv(p.stem));
  if (p.springs) p.springs->write(dir / springsCsv(p.stem));
  if (p.reactions) p.reactions->write(dir / reactionsCsv(p.stem));
  for (const std::vector<CsvTable>* list : {&p.members, &p.envelopes})
    for (const CsvTable& table : *list) table.write(dir / table.title());
  writeStaticVtu(dir / staticVtu(p.stem), {model, statics.displacement}, statics, p.stations,
                 p.extremes->own->peaks);
  if (!p.cases.empty()) {
    std::vector<PvdEntry> entries;
    for (const PreparedCase& c : p.cases) {
      writeStaticVtu(dir / c.vtu, c.outcome->on(model), c.outcome->statics, c.stations, c.peaks);
      entries.push_back({double(c.index + 1), c.vtu});  // the case's number as its time step
    }
    writePvd(dir / casesPvd(p.stem), entries);
  }
  if (charts && !p.stations.empty() && p.members.empty())
    drawChart(dir, staticDiagrams(captionOf(prepared, a.name), diagramsChart(p.stem),
                                  {{&*p.fields, fieldsCsv(p.stem), ""}}, namedPointMarkers(model),
                                  kAllDiagrams, prepared.units));
  if (charts && !p.members.empty()) drawFrameCharts(prepared, p, statics, dir);
}

/// A modal analysis' files: its frequencies, shapes, one VTK file per mode and the chart.
void writeModalFiles(const PreparedRun& prepared, const PreparedAnalysis& p, const Model& model,
                     const ModalResult& modal, const fs::path& dir, bool charts) {
  const RunResult& run = *prepared.run;
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
  if (!charts || p.shapes->rowCount() == 0) return;
  if (model.members().empty()) {
    drawChart(dir, modeShapesChart(captionOf(prepared, p.outcome->name), shapesChart(p.stem),
                                   model, modal, *p.shapes, shapesCsv(p.stem), prepared.units));
    return;
  }
  std::vector<std::string> titles;
  for (std::size_t m = 0; m < modal.modes.size(); ++m) {
    const OutputUnits::Shown hz = prepared.units.valueIn("Hz", {1, "Hz"});
    char frequency[32];
    std::snprintf(frequency, sizeof frequency, "%.4g ", modal.modes[m].frequencyHz * hz.factor);
    std::string title = "mode " + std::to_string(m + 1);
    title += ": ";
    title += frequency;
    title += hz.unit;
    title += ", ";
    title += modal.modes[m].description;
    titles.push_back(std::move(title));
  }
  drawChart(dir, frameShapesChart(captionOf(prepared, p.outcome->name), shapesChart(p.stem), model,
                                  modal.modes, titles, run.dimension == "planar", prepared.units));
}

/// Each analysis' own files (tables, VTK, charts handed to this thread's batch).
void writeAnalysisFiles(const PreparedRun& prepared, const fs::path& dir, bool charts) {
  const RunResult& run = *prepared.run;
  const Model& model = *run.model;
  for (const PreparedAnalysis& p : prepared.analyses) {
    const AnalysisOutcome& a = *p.outcome;
    std::visit(
        Overloaded{
            [&](const StaticOutcome& r) { writeStaticFiles(prepared, p, r.statics, dir, charts); },
            [&](const SecondOrderResult& r) {
              writeStaticFiles(prepared, p, r.secondOrder, dir, charts);
            },
            [&](const BucklingResult&) {
              writeBucklingFiles(p, model, dir, captionOf(prepared, a.name), charts,
                                 run.dimension == "planar", prepared.units);
            },
            [&](const ModalResult& r) { writeModalFiles(prepared, p, model, r, dir, charts); },
            [&](const TorsionOutcome& r) {
              writeModalFiles(prepared, p, *r.model, r.modes, dir, charts);
              for (const CsvTable& table : p.torsion) table.write(dir / table.title());
              if (charts)
                drawTorsionCharts(dir, r, p.stem, captionOf(prepared, a.name), prepared.units);
            },
            [&](const TransientOutcome& r) {
              writeTransientFiles(dir, model, p.stem, r, *p.history,
                                  charts ? captionOf(prepared, a.name) : "");
            },
            [&](const RotorResult auto& r) {
              writeRotorFiles(
                  {*p.rotor, p.stem, model, dir, captionOf(prepared, a.name), charts, prepared.units},
                  r);
            },
            [&](const MovingLoadOutcome& r) {
              for (const CsvTable& table : p.moving) table.write(dir / table.title());
              writeMovingVtu(dir, model, r, p.stem);
              if (charts)
                drawMovingCharts(dir, r, p.stem, captionOf(prepared, a.name), prepared.units);
            },
            [&](const ResponseSpectrumResult& r) {
              writeModalFiles(prepared, p, model, r.modal, dir, charts);
              for (const CsvTable& table : p.spectrum) table.write(dir / table.title());
              writeSpectrumFiles(dir, r, model, p.stem, captionOf(prepared, a.name), charts,
                                 prepared.units);
            },
            [&](const BaseMotionResult& r) {
              p.baseMotion->write(dir / p.baseMotion->title());
              writeBaseMotionVtu(dir, model, r, p.stem);
              if (charts)
                drawBaseMotionChart(dir, *p.baseMotion, p.stem, captionOf(prepared, a.name));
            },
            [&](const CrankSliderOutcome& r) {
              for (const CsvTable& table : p.crank) table.write(dir / table.title());
              if (charts)
                drawCrankCharts(dir, r, p.stem, captionOf(prepared, a.name), prepared.units);
            }},
        a.result);
  }
}

/// Every file of a run but its charts' images. results.json with the load cases' tables (the
/// largest file of a run with many combinations: numbers formatted one by one) is written on
/// a second core while this thread writes the analyses' own files; the files are distinct, so
/// their bytes are those of one after the other.
void writeRunFiles(const PreparedRun& prepared, const fs::path& dir, bool charts) {
  if (usableCores() < 2) {
    writeResultsAndCaseTables(prepared, dir);
    writeAnalysisFiles(prepared, dir, charts);
    return;
  }
  runParts(2, [&](int part) {
    if (part == 0)
      writeResultsAndCaseTables(prepared, dir);
    else
      writeAnalysisFiles(prepared, dir, charts);  // the caller's thread: its chart batch
  });
}

}  // namespace

void writeRunOutputs(const RunResult& run, const fs::path& dir, const OutputChoices& choices,
                     const AlsoWrite& also) {
  writePreparedRun(prepareRun(run, choices), dir, choices, also);
}

void writePreparedRun(const PreparedRun& prepared, const fs::path& dir,
                      const OutputChoices& choices, const AlsoWrite& also) {
  writeDirectoryAtomically(dir, [&](const fs::path& temporary) {
    ChartBatch charts(choices.charts);
    writeRunFiles(prepared, temporary, choices.charts != ChartFormat::none);
    charts.draw();
    if (also) also(temporary);
  });
}

void writeSweepOutputs(const SweepResult& sweep, const fs::path& dir, const OutputChoices& choices,
                       const AlsoWrite& also) {
  // 1. Prepare every value and the sweep's own tables before writing anything.
  if (sweep.values.empty()) throw std::invalid_argument("a sweep needs at least one value");
  if (sweep.runs.size() != sweep.values.size())
    throw std::invalid_argument("sweep over '" + sweep.parameter + "' has " +
                                std::to_string(sweep.values.size()) + " values but " +
                                std::to_string(sweep.runs.size()) + " runs");
  // Each value's tables only where they are written: in its own directory, or read by the
  // overlaid diagrams of a short sweep. Otherwise its results.json document alone.
  const bool tables = choices.pointFiles || sweep.values.size() <= kOverlaidValues;
  std::vector<PreparedRun> prepared;
  std::vector<Json> docs;
  std::vector<std::string> directories;  // empty names without point files
  for (std::size_t i = 0; i < sweep.runs.size(); ++i) {
    if (tables) prepared.push_back(prepareRun(sweep.runs[i], choices));
    docs.push_back(tables ? wholeResults(prepared.back()) : prepareRunDocument(sweep.runs[i]));
    directories.push_back(choices.pointFiles ? sweepValueDirectory(i, sweep.runs.size()) : "");
  }
  const Json sweepDoc = sweepJson(sweep, docs, directories);
  requireFiniteNumbers(sweepDoc, kSweepJson);
  const std::vector<SweepQuantity> quantities = sweepQuantities(docs);
  const CsvTable table = inUnits(sweepTable(kSweepCsv, sweep, docs, quantities), choices.units);

  // 2. Per value its own results when asked for (no charts: they would dominate the time of a
  // long sweep), then the sweep's JSON, CSV, a .pvd series per static analysis over the
  // values' files, and the sweep charts.
  writeDirectoryAtomically(dir, [&](const fs::path& temporary) {
    ChartBatch charts(choices.charts);
    if (choices.pointFiles)
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
        if (choices.pointFiles) {
          std::vector<PvdEntry> series;
          for (std::size_t i = 0; i < sweep.values.size(); ++i)
            series.push_back({sweep.values[i], directories[i] + "/" + staticVtu(stem)});
          writePvd(temporary / collectionPvd(stem), series);
        }
        // Diagrams along a line; a frame's members are in its own files per value. They read
        // each value's fields from its directory, or without one from a table of their own.
        const bool overlaid = sweep.values.size() <= kOverlaidValues &&
                              choices.charts != ChartFormat::none &&
                              !prepared.front().analyses[k].stations.empty() &&
                              prepared.front().analyses[k].members.empty();
        std::vector<const CsvTable*> fields;
        std::vector<std::string> files, values;
        // The swept values in the user's unit of their quantity, when they set it.
        const OutputUnits::Shown swept = choices.units.valueIn(sweep.unit, {1, ""});
        for (std::size_t i = 0; i < prepared.size() && overlaid; ++i) {
          fields.push_back(&*prepared[i].analyses[k].fields);
          files.push_back(choices.pointFiles ? directories[i] + "/" + fieldsCsv(stem)
                                             : sweepFieldsCsv(stem, i, prepared.size()));
          if (!choices.pointFiles) fields.back()->write(temporary / files.back());
          values.push_back(labelNumber(sweep.values[i] * swept.factor));
        }
        if (!values.empty() && !swept.unit.empty()) values.back() += " " + swept.unit;
        if (overlaid)
          drawOverlaidDiagrams(
              temporary,
              chartCaption(first, a.name, " at " + sweep.parameter + " = " + joinNames(values),
                           sweep.parameter, choices.units),
              diagramsChart(stem), sweep, fields, files, choices.units);
      }
      std::vector<SweepQuantity> own;
      for (const SweepQuantity& q : quantities)
        if (q.analysis == a.name) own.push_back(q);
      if (!own.empty())
        drawChart(temporary, sweepChart(first.deckName + ": " + a.name + " over " + sweep.parameter,
                                        sweepChart(stem), sweep.parameter, sweep.unit, own, table,
                                        kSweepCsv, choices.units));
    }
    charts.draw();
    if (also) also(temporary);
  });
}

}  // namespace beamrotor

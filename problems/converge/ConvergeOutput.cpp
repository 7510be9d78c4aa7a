#include "problems/converge/ConvergeOutput.hpp"

#include <sstream>

#include "problems/output/files/AtomicDirectory.hpp"
#include "problems/output/files/ChartBatch.hpp"
#include "problems/output/files/ChartParts.hpp"
#include "problems/output/files/FileNames.hpp"
#include "problems/output/files/Gnuplot.hpp"
#include "problems/deck/ShownFieldUnit.hpp"
#include "problems/output/files/TableUnits.hpp"

namespace beamrotor {

namespace {

std::string csvName(const ConvergeSeries& s) {
  return "convergence_" + s.method.name + ".csv";
}

Json optionalNumber(const std::optional<double>& v) {
  return v ? Json(*v) : Json(nullptr);
}

/// Relative error (log) against column `x` of every method's table as written (`tables`, one
/// per series), log, points joined.
ChartScript errorChart(const ConvergeStudy& study, const std::vector<CsvTable>& tables,
                       const std::string& name, const std::string& x, const std::string& xLabel) {
  // Both axes in whole decades of the drawn (positive) values.
  PositiveRange xRange, errors;
  for (std::size_t i = 0; i < study.series.size(); ++i) {
    for (const double v : tables[i].numbers(x)) xRange.include(v);
    for (const ConvergeLevel& l : study.series[i].levels) errors.include(l.error);
  }
  std::ostringstream body;
  const std::string reference = study.check.empty() ? "Richardson-extrapolated reference (estimate)"
                                                    : "closed form of check '" + study.check + "'";
  body << "  set encoding utf8\n"
       << "  set title "
       << captionText(study.deckName + ": " + study.quantity + "\nagainst the " + reference)
       << " font ',13'\n"
       << logAxis("x", xRange) << logAxis("y", errors)
       << "  set grid mxtics mytics\n  set key outside below\n"
       << "  set xlabel " << gnuplotText(xLabel) << "\n"
       << "  set ylabel 'relative error [-]'\n  plot ";
  const char* separator = "";
  for (std::size_t i = 0; i < study.series.size(); ++i) {
    const ConvergeSeries& s = study.series[i];
    if (s.levels.empty()) continue;
    const CsvTable& table = tables[i];
    const int error = table.column("rel_error");
    // Errors at round-off can be exactly 0: not drawable on a log axis, left out.
    body << separator << gnuplotFile(csvName(s)) << " skip 1 using " << table.column(x) << ":($"
         << error << " > 0 ? $" << error << " : NaN) with linespoints linewidth 2 pointtype "
         << 5 + 2 * int(i) << " " << colour(i) << " title " << gnuplotText(s.method.label);
    separator = ", \\\n       ";
  }
  body << "\n";
  return {name, "Relative error against " + xLabel + ", one line per method", 900, 650, body.str()};
}

}  // namespace

Json convergenceJson(const ConvergeStudy& study) {
  Json doc;
  doc["deck"] = {{"name", study.deckName}, {"path", study.deckPath}};
  doc["quantity"] = study.quantity;
  doc["analysis"] = study.analysis;
  doc["check"] = study.check.empty() ? Json(nullptr) : Json(study.check);
  doc["choice"] = study.choice;
  doc["refinement"] = study.refinement;
  doc["reference_kind"] = study.check.empty() ? "richardson" : "closed form";
  Json methods = Json::array();
  for (const ConvergeSeries& s : study.series) {
    Json m;
    m["name"] = s.method.name;
    m["label"] = s.method.label;
    m["reference"] = s.reference;
    m["extrapolation_order"] = optionalNumber(s.extrapolationOrder);
    Json levels = Json::array();
    for (const ConvergeLevel& l : s.levels)
      levels.push_back({{"level", l.level},
                        {"elements", l.elements},
                        {"dofs", l.dofs},
                        {"steps", l.steps},
                        {"runs", l.runs},
                        {"time_s",
                         {{"assembly", l.assembly},
                          {"factor", l.factor},
                          {"solve", l.solve},
                          {"total", l.total}}},
                        {"value", l.value},
                        {"rel_error", l.error},
                        {"order", optionalNumber(l.order)}});
    m["levels"] = std::move(levels);
    m["failure"] = s.failure.empty() ? Json(nullptr) : Json(s.failure);
    methods.push_back(std::move(m));
  }
  doc["methods"] = std::move(methods);
  doc["beamrotor_version"] = BEAMROTOR_VERSION;
  return doc;
}

CsvTable convergenceTable(const ConvergeSeries& series, const FieldUnit& unit) {
  CsvTable table(csvName(series), {{"level", ""},
                                   {"elements", ""},
                                   {"dofs", ""},
                                   {"steps", ""},
                                   {"assembly", "s"},
                                   {"factor", "s"},
                                   {"solve", "s"},
                                   {"total", "s"},
                                   {"value", bareUnitName(unit)},
                                   {"rel_error", ""}});
  for (const ConvergeLevel& l : series.levels)
    table.addRow({static_cast<long long>(l.level), static_cast<long long>(l.elements),
                  static_cast<long long>(l.dofs), static_cast<long long>(l.steps), l.assembly,
                  l.factor, l.solve, l.total, l.value, l.error});
  return table;
}

std::vector<CsvTable> convergenceTables(const ConvergeStudy& study, const OutputUnits& units) {
  std::vector<CsvTable> tables;
  for (const ConvergeSeries& s : study.series)
    tables.push_back(inUnits(convergenceTable(s, study.unit), units));
  return tables;
}

void writeConvergenceOutputs(const ConvergeStudy& study, const std::filesystem::path& dir,
                             const OutputUnits& units) {
  const Json doc = convergenceJson(study);
  requireFiniteNumbers(doc, kConvergenceJson);
  const std::vector<CsvTable> tables = convergenceTables(study, units);
  writeDirectoryAtomically(dir, [&](const std::filesystem::path& temporary) {
    // Both charts drawn together, as SVG (the verification report inlines them) and PNG.
    ChartBatch charts(ChartFormat::both);
    writeJson(doc, temporary / kConvergenceJson);
    for (const CsvTable& t : tables) t.write(temporary / t.title());
    // The size of the discretisation: free dofs on a mesh, steps in time.
    if (study.refinement == "time step")
      drawChart(temporary, errorChart(study, tables, "convergence_dofs", "steps", "time steps"));
    else
      drawChart(temporary, errorChart(study, tables, "convergence_dofs", "dofs", "free dofs"));
    drawChart(temporary, errorChart(study, tables, "convergence_time", "total",
                                    "wall time (total) [" + units.of("s").unit + "]"));
    charts.draw();
  });
}

}  // namespace beamrotor

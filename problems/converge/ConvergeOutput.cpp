#include "problems/converge/ConvergeOutput.hpp"

#include <sstream>

#include "problems/output/AtomicDirectory.hpp"
#include "problems/output/ChartParts.hpp"
#include "problems/output/FileNames.hpp"
#include "problems/output/Gnuplot.hpp"

namespace beamrotor {

namespace {

constexpr const char* kConvergenceCsv = "convergence.csv";

Json optionalNumber(const std::optional<double>& v) { return v ? Json(*v) : Json(nullptr); }

/// Relative error (log) against the column `xSuffix` of every method (log), points joined.
ChartScript errorChart(const ConvergeStudy& study, const CsvTable& table, const std::string& name,
                       const std::string& xSuffix, const std::string& xLabel) {
  std::ostringstream body;
  const std::string reference = study.check.empty()
                                    ? "Richardson-extrapolated reference (estimate)"
                                    : "closed form of check '" + study.check + "'";
  body << "  set encoding utf8\n"
       << "  set title " << captionText(study.deckName + ": " + study.quantity + "\nagainst the " +
                                        reference)
       << " font ',13'\n"
       << "  set logscale xy\n  set grid mxtics mytics\n  set key outside below\n"
       << "  set format y '10^{%L}'\n"
       << "  set xlabel " << gnuplotText(xLabel) << "\n"
       << "  set ylabel 'relative error'\n  plot ";
  for (std::size_t i = 0; i < study.series.size(); ++i) {
    const std::string& m = study.series[i].method.name;
    if (i) body << ", \\\n       ";
    // Errors at round-off can be exactly 0: not drawable on a log axis, left out.
    body << gnuplotFile(kConvergenceCsv) << " skip 1 using " << table.column(m + xSuffix)
         << ":($" << table.column(m + ".rel_error") << " > 0 ? $"
         << table.column(m + ".rel_error") << " : NaN) with linespoints linewidth 2 pointtype "
         << 5 + 2 * int(i) << " " << colour(i) << " title "
         << gnuplotText(study.series[i].method.label);
  }
  body << "\n";
  return {name, "Relative error against " + xLabel + ", one line per method", 900, 650,
          body.str()};
}

}  // namespace

Json convergenceJson(const ConvergeStudy& study) {
  Json doc;
  doc["deck"] = {{"name", study.deckName}, {"path", study.deckPath}};
  doc["quantity"] = study.quantity;
  doc["analysis"] = study.analysis;
  doc["check"] = study.check.empty() ? Json(nullptr) : Json(study.check);
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
    methods.push_back(std::move(m));
  }
  doc["methods"] = std::move(methods);
  doc["beamrotor_version"] = BEAMROTOR_VERSION;
  return doc;
}

CsvTable convergenceTable(const ConvergeStudy& study) {
  std::vector<CsvColumn> columns{{"level", ""}};
  for (const ConvergeSeries& s : study.series) {
    const std::string& m = s.method.name;
    columns.push_back({m + ".dofs", ""});
    columns.push_back({m + ".time", "s"});
    columns.push_back({m + ".value", ""});
    columns.push_back({m + ".rel_error", ""});
  }
  CsvTable table(kConvergenceCsv, columns);
  const std::size_t levels = study.series.empty() ? 0 : study.series.front().levels.size();
  for (std::size_t k = 0; k < levels; ++k) {
    std::vector<CsvCell> row{static_cast<long long>(k)};
    for (const ConvergeSeries& s : study.series) {
      const ConvergeLevel& l = s.levels[k];
      row.insert(row.end(), {static_cast<long long>(l.dofs), l.total, l.value, l.error});
    }
    table.addRow(std::move(row));
  }
  return table;
}

void writeConvergenceOutputs(const ConvergeStudy& study, const std::filesystem::path& dir) {
  const Json doc = convergenceJson(study);
  requireFiniteNumbers(doc, kConvergenceJson);
  const CsvTable table = convergenceTable(study);
  writeDirectoryAtomically(dir, [&](const std::filesystem::path& temporary) {
    writeJson(doc, temporary / kConvergenceJson);
    table.write(temporary / kConvergenceCsv);
    drawChart(temporary, errorChart(study, table, "convergence_dofs", ".dofs", "free dofs"));
    drawChart(temporary,
              errorChart(study, table, "convergence_time", ".time", "wall time (total) [s]"));
  });
}

}  // namespace beamrotor

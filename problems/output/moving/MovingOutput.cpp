#include "problems/output/moving/MovingOutput.hpp"

#include <algorithm>
#include <cmath>
#include <sstream>

#include "problems/output/files/ChartParts.hpp"
#include "problems/output/files/Gnuplot.hpp"
#include "problems/output/moving/MovingVtk.hpp"

namespace beamrotor {

namespace {

/// Samples per element of the path in the table and chart (the lines are cubics there).
constexpr int kSamplesPerPiece = 8;

std::string influenceCsv(const std::string& stem) {
  return stem + "_influence.csv";
}
std::string envelopesCsv(const std::string& stem) {
  return stem + "_envelopes.csv";
}

/// A quantity's text as a column name: its words joined by '_'.
std::string columnName(const std::string& text) {
  std::string out = text;
  std::replace(out.begin(), out.end(), ' ', '_');
  return out;
}

/// The places sampled along the path, each with the piece it is read in: every piece from its
/// start to its end, so a break appears twice (the end of one piece, the start of the next).
struct Sample {
  double s = 0;
  std::size_t piece = 0;
  double t = 0;
};
std::vector<Sample> samplesOf(const InfluenceLine& line) {
  std::vector<Sample> out;
  for (std::size_t p = 0; p < line.pieces.size(); ++p)
    for (int k = 0; k <= kSamplesPerPiece; ++k) {
      const double t = double(k) / kSamplesPerPiece;
      out.push_back({line.breaks[p] + t * (line.breaks[p + 1] - line.breaks[p]), p, t});
    }
  return out;
}

CsvTable influenceTable(const MovingLoadOutcome& m, const std::string& stem) {
  std::vector<CsvColumn> columns{{"s", "m"}};
  for (const MovingQuantity& q : m.quantities) columns.push_back({columnName(q.text), q.unit});
  CsvTable t(influenceCsv(stem), columns);
  for (const Sample& x : samplesOf(m.quantities.front().line)) {
    std::vector<CsvCell> row{x.s};
    for (const MovingQuantity& q : m.quantities)
      row.push_back(valueAt(q.line.pieces[x.piece], x.t));
    t.addRow(row);
  }
  return t;
}

/// Quantities of several kinds share the value columns: each row names its unit (`units`'
/// of the quantity's, SI where none is set), its numbers converted into it here.
CsvTable envelopesTable(const MovingLoadOutcome& m, const std::string& stem,
                        const OutputUnits& units) {
  CsvTable t(envelopesCsv(stem), {{"quantity", ""},
                                  {"unit", ""},
                                  {"deck_loads", ""},
                                  {"max", ""},
                                  {"first_wheel_at_max", "m"},
                                  {"min", ""},
                                  {"first_wheel_at_min", "m"}});
  for (const MovingQuantity& q : m.quantities) {
    const OutputUnits::Shown shown = units.of(q.valueUnit);
    t.addRow({q.text, shown.unit, q.deckValue * shown.factor, q.envelope.max.value * shown.factor,
              q.envelope.max.lead,
              q.envelope.min.value * shown.factor, q.envelope.min.lead});
  }
  return t;
}

Json extremeJson(const TrainExtreme& e) {
  return {{"value", e.value}, {"first_wheel_at", e.lead}};
}

}  // namespace

std::vector<CsvTable> movingTables(const MovingLoadOutcome& m, const std::string& stem,
                                   const OutputUnits& units) {
  return {influenceTable(m, stem), envelopesTable(m, stem, units)};
}

Json movingJson(const AnalysisOutcome& a, const std::string& stem) {
  const MovingLoadOutcome& m = *resultOf<MovingLoadOutcome>(a);
  Json wheels = Json::array();
  for (const TrainLoad& w : m.train) wheels.push_back({{"force", w.force}, {"offset", w.offset}});
  Json quantities = Json::array();
  for (const MovingQuantity& q : m.quantities) {
    Json pieces = Json::array();
    for (const Polynomial& p : q.line.pieces) pieces.push_back(p);
    quantities.push_back({{"quantity", q.text},
                          {"unit", q.valueUnit},
                          {"influence_unit", q.unit},
                          {"deck_loads_value", q.deckValue},
                          {"max", extremeJson(q.envelope.max)},
                          {"min", extremeJson(q.envelope.min)},
                          {"influence", {{"breaks", q.line.breaks}, {"pieces", pieces}}}});
  }
  return {{"type", a.type},
          {"name", a.name},
          {"path_length", m.length},
          {"direction", m.direction},
          {"deck_loads", m.deckLoads},
          {"wheels", wheels},
          {"quantities", quantities},
          {"files",
           {{"influence_csv", influenceCsv(stem)},
            {"envelopes_csv", envelopesCsv(stem)},
            {"influence_chart", stem + "_influence.svg"},
            {"envelope_vtu", movingVtu(stem)}}}};
}

void drawMovingCharts(const std::filesystem::path& dir, const MovingLoadOutcome& m,
                      const std::string& stem, const std::string& caption,
                      const OutputUnits& units) {
  const int panels = int(m.quantities.size());
  const int width = 1000, height = 120 + 300 * panels;
  // Places along the path, the influence per unit load and the effects under the train, each
  // in the user's unit of its quantity where set (SI otherwise).
  const OutputUnits::Shown length = units.of("m");
  std::ostringstream data, body;
  for (std::size_t i = 0; i < m.quantities.size(); ++i) {
    const double influence = units.of(m.quantities[i].unit).factor;
    data << "$line" << i << " << EOD\n";
    for (const Sample& x : samplesOf(m.quantities[i].line))
      data << number(x.s * length.factor) << ","
           << number(valueAt(m.quantities[i].line.pieces[x.piece], x.t) * influence) << "\n";
    data << "EOD\n";
    // The wheels where the largest and smallest effects put them, on the line.
    for (const auto& [block, extreme] :
         {std::pair{"max", m.quantities[i].envelope.max}, {"min", m.quantities[i].envelope.min}}) {
      data << "$" << block << i << " << EOD\n";
      for (const TrainLoad& w : m.train) {
        const double s = extreme.lead - w.offset;
        if (s >= 0 && s <= m.length)
          data << number(s * length.factor) << ","
               << number(m.quantities[i].line.at(s) * influence) << "\n";
      }
      data << "EOD\n";
    }
  }
  body << "  set encoding utf8\n"
       << panelLayout(panels, 1, caption, width, height,
                      30 + keyWidth({"per unit load", "wheels at max", "wheels at min"}))
       << "  set grid\n"
       << "  set xzeroaxis linetype 1 linecolor rgb 'gray40'\n"
       << "  set key outside right top\n  set xrange [0:" << number(m.length * length.factor)
       << "]\n";
  for (std::size_t i = 0; i < m.quantities.size(); ++i) {
    const MovingQuantity& q = m.quantities[i];
    const OutputUnits::Shown value = units.of(q.valueUnit);
    const auto place = [&](double s) { return labelNumber(s * length.factor) + " " + length.unit; };
    if (i + 1 == m.quantities.size())
      body << "  set xlabel "
           << gnuplotText("unit load at s along the path [" + length.unit + "]") << "\n";
    const OutputUnits::Shown perLoad = units.of(q.unit);
    body << "  set ylabel " << gnuplotText(q.text + " [" + perLoad.unit + "]") << "\n";
    std::string title = "influence line of " + q.text + "; under the train max ";
    title += labelNumber(q.envelope.max.value * value.factor) + " " + value.unit;
    // Appended piece by piece: `" (at " + temporary` trips GCC 12's false -Wrestrict.
    title += " (first wheel at ";
    title += place(q.envelope.max.lead);
    title += "), min ";
    title += labelNumber(q.envelope.min.value * value.factor) + " " + value.unit;
    title += " (at ";
    title += place(q.envelope.min.lead);
    title += ")";
    body << "  set title " << gnuplotText(title) << "\n";
    body << "  plot $line" << i << " using 1:2 with lines linewidth 2 " << colour(0)
         << " title " << gnuplotText("per unit load") << ", \\\n       $max" << i
         << " using 1:2 with points pointtype 7 pointsize 1.5 " << colour(1) << " title "
         << gnuplotText("wheels at max") << ", \\\n       $min" << i
         << " using 1:2 with points pointtype 6 pointsize 1.8 " << colour(2) << " title "
         << gnuplotText("wheels at min") << "\n";
  }
  body << "  unset multiplot\n";
  drawChart(dir, {stem + "_influence", "Influence lines of a moving load and their envelopes",
                  width, height, body.str(), data.str()});
}

}  // namespace beamrotor

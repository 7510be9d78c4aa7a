#include "problems/output/crank/CrankOutput.hpp"

#include <cmath>
#include <numbers>
#include <sstream>

#include "problems/output/files/ChartParts.hpp"
#include "problems/output/files/Gnuplot.hpp"

namespace beamrotor {

namespace {

constexpr double kCrankDegree = 180 / std::numbers::pi;

std::string motionCsv(const std::string& stem) {
  return stem + "_motion.csv";
}
std::string harmonicsCsv(const std::string& stem) {
  return stem + "_harmonics.csv";
}
std::string lambdaCsv(const std::string& stem) {
  return stem + "_lambda_table.csv";
}

/// Sum over the cranks of cos(k (phi + theta_j)).
double phasedCosines(const std::vector<double>& phases, int k, double phi) {
  double sum = 0;
  for (double theta : phases) sum += std::cos(k * (phi + theta));
  return sum;
}

CsvTable motionTable(const CrankSliderOutcome& c, const std::string& stem) {
  std::vector<CsvColumn> columns{
      {"phi", "deg"},         {"x", "m"},          {"x_approx", "m"},     {"v", "m/s"},
      {"v_approx", "m/s"},    {"a", "m/s^2"},      {"a_approx", "m/s^2"}, {"beta", "rad"},
      {"beta_approx", "rad"}, {"beta_dot", "rad/s"}, {"beta_ddot", "rad/s^2"}};
  const bool loads = c.reduced.has_value();
  if (loads)
    for (const char* name : {"F1_term", "F2_term", "inertia_force", "cranks_F1_term",
                             "cranks_F2_term", "cranks_force"})
      columns.push_back({name, "N"});
  if (loads) columns.push_back({"rod_couple", "N m"});
  CsvTable t(motionCsv(stem), columns);
  for (std::size_t i = 0; i < c.samples.size(); ++i) {
    const CrankSample& s = c.samples[i];
    const double phi = s.exact.phi;
    std::vector<CsvCell> row{phi * kCrankDegree, s.exact.x,       s.approximate.x, s.exact.v,
                             s.approximate.v,    s.exact.a,       s.approximate.a, s.exact.beta,
                             s.approximate.beta, s.exact.betaDot, s.exact.betaDDot};
    if (loads) {
      // The inertia force -m_rec a as its first two cos(k phi) terms, per crank and summed.
      const double f1 = -c.harmonics[0], f2 = -c.harmonics[1];
      row.insert(row.end(),
                 {f1 * std::cos(phi), f2 * std::cos(2 * phi), s.inertiaForce,
                  f1 * phasedCosines(c.input.phases, 1, phi),
                  f2 * phasedCosines(c.input.phases, 2, phi), s.cranksForce, s.rodCouple});
    }
    t.addRow(row);
  }
  return t;
}

CsvTable harmonicsTable(const CrankSliderOutcome& c, const std::string& stem) {
  CsvTable t(
      harmonicsCsv(stem),
      {{"force", ""}, {"order", ""}, {"one_crank", "N"}, {"phase_sum", ""}, {"all_cranks", "N"}});
  static constexpr int kOrders[] = {1, 2, 4, 6};
  for (std::size_t i = 0; i < 4; ++i)
    t.addRow({std::string("reciprocating"), (long long)kOrders[i], c.harmonics[i],
              c.harmonics[i] > 0 ? c.cranksHarmonics[i] / c.harmonics[i] : 0.0,
              c.cranksHarmonics[i]});
  t.addRow({std::string("rotating"), 1LL, c.rotatingForce,
            c.rotatingForce > 0 ? c.cranksRotating / c.rotatingForce : 0.0, c.cranksRotating});
  return t;
}

CsvTable lambdaTable(const CrankSliderOutcome& c, const std::string& stem) {
  CsvTable t(lambdaCsv(stem), {{"lambda", ""},
                               {"A2", ""},
                               {"A4", ""},
                               {"A6", ""},
                               {"v_ratio", ""},
                               {"K_lambda", "(rad/s)^2/rpm^2"}});
  for (const CrankLambdaRow& r : c.table)
    t.addRow({r.lambda, r.series.A2, r.series.A4, r.series.A6, r.vRatio, r.kLambda});
  return t;
}

/// One plotted curve of the motion table.
struct CrankCurve {
  const char* column;
  const char* title;
  double scale;
  bool dashed;
};

std::string crankPlot(const CsvTable& table, const std::string& file,
                      const std::vector<CrankCurve>& lines) {
  std::ostringstream s;
  s << "  plot ";
  for (std::size_t i = 0; i < lines.size(); ++i) {
    if (i) s << ", \\\n       ";
    s << gnuplotFile(file) << " skip 1 using " << table.column("phi") << ":($"
      << table.column(lines[i].column) << "*" << number(lines[i].scale)
      << ") with lines linewidth 2 " << (lines[i].dashed ? "dashtype 2 " : "") << colour(i)
      << " title " << gnuplotText(lines[i].title);
  }
  return s.str() + "\n";
}

/// A panel's axis: its quantity and unit, e.g. "slider position x [mm]".
std::string axisLabel(const std::string& quantity, const OutputUnits::Shown& unit) {
  return quantity + " [" + unit.unit + "]";
}

std::string panelsBody(const CsvTable& table, const std::string& file, const std::string& caption,
                       int width, int height,
                       const std::vector<std::pair<std::string, std::vector<CrankCurve>>>& panels,
                       const OutputUnits& units) {
  // One turn of the crank, in degrees or the user's angle unit (the table's phi holds it).
  const double degree = units.valueIn("deg", {1, "deg"}).factor;
  std::ostringstream body;
  body << "  set encoding utf8\n"
       << panelLayout(int(panels.size()), 1, caption, width, height, 230) << "  set grid\n"
       << "  set xzeroaxis linetype 1 linecolor rgb 'gray40'\n"
       << "  set key outside right top\n  set xrange [0:" << number(360 * degree)
       << "]\n  set xtics 0, " << number(45 * degree) << ", " << number(360 * degree) << "\n";
  for (std::size_t p = 0; p < panels.size(); ++p) {
    if (p + 1 == panels.size())
      body << "  set xlabel "
           << gnuplotText(axisLabel("crank angle φ", units.columnIn("deg", {1, "deg"}))) << "\n";
    body << "  set ylabel " << gnuplotText(panels[p].first) << "\n"
         << crankPlot(table, file, panels[p].second);
  }
  body << "  unset multiplot\n";
  return body.str();
}

}  // namespace

std::vector<CsvTable> crankTables(const CrankSliderOutcome& c, const std::string& stem) {
  std::vector<CsvTable> out{motionTable(c, stem)};
  if (c.reduced) out.push_back(harmonicsTable(c, stem));
  if (!c.table.empty()) out.push_back(lambdaTable(c, stem));
  return out;
}

Json crankJson(const AnalysisOutcome& a, const std::string& stem) {
  const CrankSliderOutcome& c = *resultOf<CrankSliderOutcome>(a);
  const crank::Geometry& g = c.input.geometry;
  Json phases = Json::array();
  for (double theta : c.input.phases) phases.push_back(theta * kCrankDegree);
  Json out = {{"type", a.type},
              {"name", a.name},
              {"r", g.r},
              {"l", g.l},
              {"lambda", c.lambda},
              {"speed_rpm", c.input.speed * 30 / std::numbers::pi},
              {"omega", c.input.speed},
              {"cranks_deg", phases},
              {"v_max", c.vMax},
              {"v_mean", c.vMean},
              {"v_ratio", c.vMax / c.vMean},
              {"a_max", c.aMax},
              {"beta_max", c.betaMax},
              {"beta_dot_max", c.betaDotMax},
              {"beta_ddot_max", c.betaDDotMax},
              {"beta_ddot_max_first_order", c.betaDDotMaxFirstOrder},
              {"series", {{"A2", c.series.A2}, {"A4", c.series.A4}, {"A6", c.series.A6}}}};
  Json files = {{"motion_csv", motionCsv(stem)}, {"kinematics_chart", stem + "_kinematics.svg"}};
  if (c.reduced) {
    out["masses"] = {{"rotating", c.reduced->rotating},
                     {"reciprocating", c.reduced->reciprocating},
                     {"eccentric_at_pin", c.reduced->eccentricAtPin},
                     {"rod_at_crank_pin", c.reduced->rodBigEnd},
                     {"rod_at_slider_pin", c.reduced->rodSmallEnd}};
    out["inertia"] = {{"F1", c.harmonics[0]},
                      {"F2", c.harmonics[1]},
                      {"F4", c.harmonics[2]},
                      {"F6", c.harmonics[3]},
                      {"F_rotating", c.rotatingForce},
                      {"F1_total", c.rotatingForce + c.harmonics[0]},
                      {"F2_total", c.harmonics[1]},
                      {"cranks_F1", c.cranksHarmonics[0]},
                      {"cranks_F2", c.cranksHarmonics[1]},
                      {"cranks_F4", c.cranksHarmonics[2]},
                      {"cranks_F6", c.cranksHarmonics[3]},
                      {"cranks_rotating", c.cranksRotating},
                      {"moment_max", c.momentMax},
                      {"moment_max_first_order", c.momentMaxFirstOrder}};
    files["harmonics_csv"] = harmonicsCsv(stem);
    files["harmonics_chart"] = stem + "_inertia_harmonics.svg";
  }
  if (c.delivery > 0) out["delivery"] = {{"m3_s", c.delivery}, {"l_min", c.delivery * 60e3}};
  if (!c.table.empty()) files["lambda_csv"] = lambdaCsv(stem);
  out["files"] = files;
  return out;
}

void drawCrankCharts(const std::filesystem::path& dir, const CrankSliderOutcome& c,
                     const std::string& stem, const std::string& caption,
                     const OutputUnits& units) {
  const CsvTable motion = motionTable(c, stem);
  const std::string file = motionCsv(stem);
  const int width = 1030;
  const OutputUnits::Shown x = units.columnIn("m", {1e3, "mm"});
  const OutputUnits::Shown v = units.columnIn("m/s", {1, "m/s"});
  const OutputUnits::Shown a = units.columnIn("m/s^2", {1, "m/s²"});
  const OutputUnits::Shown force = units.columnIn("N", {1, "N"});
  drawChart(dir, {stem + "_kinematics",
                  "Slider position, velocity and acceleration against the crank angle", width, 1100,
                  panelsBody(motion, file, caption, width, 1100,
                             {{axisLabel("slider position x", x),
                               {{"x", "exact", x.factor, false},
                                {"x_approx", "two-term", x.factor, true}}},
                              {axisLabel("slider velocity v", v),
                               {{"v", "exact", v.factor, false},
                                {"v_approx", "two-term", v.factor, true}}},
                              {axisLabel("slider acceleration a", a),
                               {{"a", "exact", a.factor, false},
                                {"a_approx", "two-term", a.factor, true}}}},
                             units)});
  if (!c.reduced) return;
  const std::string cranks = std::to_string(c.input.phases.size()) + " cranks";
  drawChart(dir, {stem + "_inertia_harmonics",
                  "First and second harmonics of the reciprocating inertia force", width, 800,
                  panelsBody(motion, file, caption, width, 800,
                             {{axisLabel("one crank", force),
                               {{"F1_term", "1st harmonic", force.factor, false},
                                {"F2_term", "2nd harmonic", force.factor, false},
                                {"inertia_force", "exact force", force.factor, false}}},
                              {axisLabel("sum over the " + cranks, force),
                               {{"cranks_F1_term", "1st harmonics", force.factor, false},
                                {"cranks_F2_term", "2nd harmonics", force.factor, false},
                                {"cranks_force", "exact sum", force.factor, false}}}},
                             units)});
}

}  // namespace beamrotor

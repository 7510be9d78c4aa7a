// The CSV tables of the rotor analyses (see RotorTables.hpp).
#include "problems/output/rotor/RotorTables.hpp"

#include <cmath>
#include <numbers>

#include "problems/output/rotor/UnwrappedPhase.hpp"

namespace beamrotor {

long long whirlSign(Whirl w) {
  return w == Whirl::forward ? 1 : w == Whirl::backward ? -1 : 0;
}

double rpmOf(double speed) {
  return speed * 30 / std::numbers::pi;
}

CsvCell logDecrementCell(double delta) {
  // A NaN is no decrement but a fault: it stays a number, for the table to refuse.
  return std::isinf(delta) ? CsvCell(std::monostate()) : CsvCell(delta);
}

CsvTable journalBearingsTable(const std::string& title,
                              const std::vector<JournalBearingCurve>& journals) {
  CsvTable table(title, {{"bearing", ""},        {"bearing_index", ""}, {"speed", "rad/s"},
                         {"speed_rpm", "rpm"},   {"eccentricity", ""},  {"attitude_angle", "deg"},
                         {"sommerfeld", ""},     {"kxx", "N/m"},        {"kxy", "N/m"},
                         {"kyx", "N/m"},         {"kyy", "N/m"},        {"cxx", "N s/m"},
                         {"cxy", "N s/m"},       {"cyx", "N s/m"},      {"cyy", "N s/m"}});
  for (std::size_t j = 0; j < journals.size(); ++j) {
    const JournalBearingCurve& b = journals[j];
    for (std::size_t s = 0; s < b.speeds.size(); ++s) {
      const BearingCoefficients& k = b.coefficients[s];
      table.addRow({b.name, (long long)(j + 1), b.speeds[s], rpmOf(b.speeds[s]),
                    b.eccentricity[s], b.attitude[s] * 180 / std::numbers::pi, b.sommerfeld[s],
                    k.kyy, k.kyz, k.kzy, k.kzz, k.cyy, k.cyz, k.czy, k.czz});
    }
  }
  return table;
}

CsvTable api684Table(const std::string& title, const UnbalanceOutcome& r) {
  CsvTable table(title, {{"point", ""},
                         {"peak", ""},
                         {"speed_rpm", "rpm"},
                         {"amplitude", "m"},
                         {"lower_half_power_rpm", "rpm"},
                         {"upper_half_power_rpm", "rpm"},
                         {"amplification_factor", ""},
                         {"amplification_method", ""},
                         {"modal_damping_ratio", ""},
                         {"required_margin", "%"},
                         {"actual_margin", "%"},
                         {"pass", ""}});
  for (std::size_t k = 0; k < r.peaks.size(); ++k)
    for (std::size_t i = 0; i < r.peaks[k].size(); ++i) {
      const ResponsePeak& p = r.peaks[k][i];
      table.addRow({r.responsePoints[k], (long long)(i + 1), rpmOf(p.speed), p.amplitude,
                    rpmOf(p.lowerHalfPower), rpmOf(p.upperHalfPower), p.amplificationFactor,
                    std::string(amplificationMethodName(p.method)), p.dampingRatio,
                    p.requiredMargin, p.actualMargin, (long long)(p.pass ? 1 : 0)});
    }
  return table;
}

CsvTable frequencyResponseTable(const std::string& title, const FrequencyResponseResult& f) {
  CsvTable table(title, {{"frequency", "Hz"},
                         {"omega", "rad/s"},
                         {"magnitude", "m/N"},
                         {"phase", "deg"},
                         {"real", "m/N"},
                         {"imag", "m/N"}});
  const std::vector<double> phase = unwrappedPhases(f.receptance);
  for (std::size_t i = 0; i < f.frequencies.size(); ++i) {
    const std::complex<double> h = f.receptance[i];
    table.addRow({f.frequencies[i] / (2 * std::numbers::pi), f.frequencies[i], std::abs(h),
                  phase[i], h.real(), h.imag()});
  }
  return table;
}

CsvTable rotorModesTable(const std::string& title, const RotorModesResult& r) {
  CsvTable table(title, {{"mode", ""},
                         {"frequency", "Hz"},
                         {"natural_frequency", "Hz"},
                         {"damping_ratio", ""},
                         {"log_decrement", ""},
                         {"whirl", ""},
                         {"whirl_ratio", ""},
                         {"whirl_iterations", ""},
                         {"energy_in", ""},
                         {"bearing_energy", ""}});
  // The rotor's modes, then the bearings' own (tilting pads kept as dofs), numbered on.
  std::size_t number = 0;
  for (const auto* modes : {&r.modes, &r.bearingModes})
    for (const RotorMode& mode : *modes) {
      // whirl_iterations: 0 with the synchronous set, else the eigen-solutions that found the
      // mode with whirl-dependent bearings at its own eigenvalue.
      table.addRow({(long long)(++number), mode.dampedFrequencyHz, mode.naturalFrequencyHz,
                    mode.dampingRatio, logDecrementCell(mode.logDecrement),
                    std::string(whirlName(mode.whirl)), mode.whirlRatio,
                    (long long)mode.whirlIterations, std::string(energyIn(mode)),
                    mode.bearingEnergy});
    }
  return table;
}

std::string campbellColumn(int line, const std::string& what) {
  return "line" + std::to_string(line) + "_" + what;
}

int campbellLineCount(const CsvTable& campbell) {
  constexpr int kSpeedColumns = 2, kColumnsPerLine = 5;
  return int((campbell.columns().size() - kSpeedColumns) / kColumnsPerLine);
}

CsvTable campbellTable(const std::string& title, const CampbellResult& c) {
  std::vector<CsvColumn> columns{{"speed", "rad/s"}, {"speed_rpm", "rpm"}};
  for (int l = 1; l <= int(c.lines.size()); ++l) {
    columns.push_back({campbellColumn(l, "frequency"), "Hz"});
    columns.push_back({campbellColumn(l, "damping_ratio"), ""});
    columns.push_back({campbellColumn(l, "log_decrement"), ""});
    columns.push_back({campbellColumn(l, "whirl"), ""});
    columns.push_back({campbellColumn(l, "mac"), ""});
  }
  CsvTable table(title, columns);
  for (std::size_t s = 0; s < c.speeds.size(); ++s) {
    std::vector<CsvCell> row{c.speeds[s], rpmOf(c.speeds[s])};
    for (std::size_t l = 0; l < c.lines.size(); ++l) {
      const RotorMode& m = c.lines[l][s];
      row.insert(row.end(), {m.dampedFrequencyHz, m.dampingRatio, logDecrementCell(m.logDecrement),
                             whirlSign(m.whirl), c.mac[l][s]});
    }
    table.addRow(std::move(row));
  }
  return table;
}

CsvTable criticalSpeedsTable(const std::string& title, const std::vector<CriticalSpeed>& c) {
  CsvTable table(title, {{"speed_rpm", "rpm"},
                         {"speed", "rad/s"},
                         {"frequency", "Hz"},
                         {"line", ""},
                         {"damping_ratio", ""},
                         {"whirl", ""},
                         {"order", ""}});
  for (const CriticalSpeed& k : c)
    table.addRow({k.rpm, k.speed, k.frequencyHz, (long long)(k.line + 1), k.dampingRatio,
                  whirlSign(k.whirl), k.order});
  return table;
}

CsvTable unbalanceTable(const std::string& title, const UnbalanceResult& u,
                        const std::vector<std::string>& points) {
  std::vector<CsvColumn> columns{{"speed", "rad/s"}, {"speed_rpm", "rpm"}};
  for (const std::string& p : points)
    for (const auto& [what, unit] :
         std::vector<std::pair<std::string, std::string>>{{"amplitude", "m"},
                                                          {"uy_amplitude", "m"},
                                                          {"uz_amplitude", "m"},
                                                          {"uy_phase", "deg"},
                                                          {"uz_phase", "deg"}})
      columns.push_back({p + "_" + what, unit});
  CsvTable table(title, columns);
  std::vector<UnbalancePhases> phases;
  for (std::size_t k = 0; k < points.size(); ++k) phases.push_back(unbalancePhases(u.orbits[k]));
  for (std::size_t s = 0; s < u.speeds.size(); ++s) {
    std::vector<CsvCell> row{u.speeds[s], rpmOf(u.speeds[s])};
    for (std::size_t k = 0; k < points.size(); ++k) {
      const Orbit& o = u.orbits[k][s];
      row.insert(row.end(), {o.major(), std::abs(o.uy), std::abs(o.uz), phases[k].uy[s],
                             phases[k].uz[s]});
    }
    table.addRow(std::move(row));
  }
  return table;
}

}  // namespace beamrotor

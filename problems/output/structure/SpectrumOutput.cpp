#include "problems/output/structure/SpectrumOutput.hpp"

#include <algorithm>
#include <cmath>
#include <map>
#include <numbers>
#include <sstream>

#include "fem/assembly/MemberExtrema.hpp"
#include "problems/output/files/ChartParts.hpp"
#include "problems/output/files/FileNames.hpp"
#include "problems/output/files/Gnuplot.hpp"
#include "problems/output/structure/VtkWriter.hpp"

namespace beamrotor {

namespace {

const char* ruleName(ModalRule r) { return r == ModalRule::cqc ? "CQC" : "SRSS"; }
const char* directionalName(DirectionalRule r) {
  return r == DirectionalRule::srss ? "SRSS" : "100/30";
}

double periodOf(const Mode& m) { return 2 * std::numbers::pi / std::sqrt(m.eigenvalue); }

CsvTable modesTable(const ResponseSpectrumResult& r, const std::string& stem) {
  std::vector<CsvColumn> columns{{"mode", ""}, {"frequency", "Hz"}, {"period", "s"},
                                 {"Sa", "m/s^2"}, {"Sd", "m"}};
  if (r.verticalSpectrum) columns.push_back({"Sa_vertical", "m/s^2"});
  for (const char* d : {"x", "y", "z"}) columns.push_back({std::string("gamma_") + d, "kg^0.5"});
  for (const char* d : {"x", "y", "z"}) columns.push_back({std::string("mass_") + d, "kg"});
  for (const char* d : {"x", "y", "z"}) columns.push_back({std::string("cumulative_") + d, ""});
  CsvTable t(stem + "_spectrum_modes.csv", columns);
  std::array<double, 3> sum{};
  for (std::size_t j = 0; j < r.modal.modes.size(); ++j) {
    const Mode& m = r.modal.modes[j];
    std::vector<CsvCell> row;  // filled in place: GCC 12 misreads a braced list of variants
    row.reserve(columns.size());
    row.emplace_back((long long)(j + 1));
    for (double v : {m.frequencyHz, periodOf(m), r.spectralAcceleration[j],
                     r.spectralAcceleration[j] / m.eigenvalue})
      row.emplace_back(v);
    if (r.verticalSpectrum) row.emplace_back(r.saOf(j, r.vertical));
    for (double g : m.participation) row.push_back(g);
    for (double e : m.effectiveMass) row.push_back(e);
    for (int d = 0; d < 3; ++d) {
      sum[d] += m.effectiveMass[d];
      row.push_back(r.modal.totalMass[d] > 0 ? sum[d] / r.modal.totalMass[d] : 0.0);
    }
    t.addRow(std::move(row));
  }
  return t;
}

CsvTable displacementsTable(const ResponseSpectrumResult& r, const Model& model,
                            const std::string& stem) {
  CsvTable t(stem + "_spectrum_displacements.csv",
             {{"node", ""}, {"point", ""}, {"x", "m"}, {"y", "m"}, {"z", "m"}, {"ux", "m"},
              {"uy", "m"}, {"uz", "m"}, {"rx", "rad"}, {"ry", "rad"}, {"rz", "rad"}});
  std::map<int, std::string> names;
  for (const auto& [name, node] : model.namedNodes()) names[node] = name;
  for (int n = 0; n < model.nodeCount(); ++n) {
    const Eigen::Vector3d& x = model.nodes()[n];
    std::vector<CsvCell> row;  // filled in place: GCC 12 misreads a braced list of variants
    row.reserve(11);
    row.emplace_back((long long)n);
    row.emplace_back(names.count(n) ? names[n] : std::string());
    for (int k = 0; k < 3; ++k) row.emplace_back(x[k]);
    for (int k = 0; k < kDofKinds; ++k) row.push_back(r.combined.displacement(n, k));
    t.addRow(std::move(row));
  }
  return t;
}

/// Forces and moments share the value columns: each row names its unit (the force unit, or
/// force x length for a moment, of `units`), its numbers converted into it here.
CsvTable reactionsTable(const ResponseSpectrumResult& r, const std::string& stem,
                        const OutputUnits& units) {
  std::vector<CsvColumn> columns{{"support", ""}, {"dof", ""}, {"unit", ""}, {"combined", ""}};
  for (int d : r.directions) columns.push_back({std::string("from_") + directionName(d), ""});
  CsvTable t(stem + "_spectrum_reactions.csv", columns);
  const OutputUnits::Shown force = units.of("N"), moment = units.of("N m");
  for (std::size_t i = 0; i < r.combined.reactions.size(); ++i) {
    const ReactionComponent& c = r.combined.reactions[i];
    const OutputUnits::Shown& shown = isRotation(c.dof) ? moment : force;
    std::vector<CsvCell> row;  // filled in place: GCC 12 misreads a braced list of variants
    row.reserve(columns.size());
    // Each cell made in place (GCC 12's false -Wmaybe-uninitialized on moved variants).
    row.emplace_back(std::in_place_type<std::string>, c.support);
    row.emplace_back(std::in_place_type<std::string>, dofName(c.dof));
    row.emplace_back(std::in_place_type<std::string>, shown.unit);
    row.emplace_back(std::in_place_type<double>, c.value * shown.factor);
    for (const PeakResponse& p : r.perDirection)
      row.emplace_back(std::in_place_type<double>, p.reactions[i].value * shown.factor);
    t.addRow(std::move(row));
  }
  return t;
}

CsvTable membersTable(const ResponseSpectrumResult& r, const Model& model,
                      const std::string& stem) {
  CsvTable t(stem + "_spectrum_members.csv",
             {{"member", ""}, {"element", ""}, {"s", ""}, {"x", "m"}, {"y", "m"}, {"z", "m"},
              {"N", "N"}, {"Vy", "N"}, {"Vz", "N"}, {"T", "N m"}, {"My", "N m"}, {"Mz", "N m"}});
  std::map<int, std::string> memberOf;
  for (const auto& [name, elements] : model.members())
    for (int e : elements) memberOf[e] = name;
  for (const BeamStation& s : r.combined.stations) {
    const SectionForces& f = s.forces;
    std::vector<CsvCell> row;  // filled in place: GCC 12 misreads a braced list of variants
    row.reserve(12);
    row.emplace_back(memberOf.count(s.element) ? memberOf[s.element] : std::string());
    row.emplace_back((long long)s.element);
    for (double v : {s.s, s.position.x(), s.position.y(), s.position.z(), f.N, f.Vy, f.Vz, f.T,
                     f.My, f.Mz})
      row.emplace_back(v);
    t.addRow(std::move(row));
  }
  return t;
}

/// One row per quantity and combination of the directions: the base force along each
/// direction, each dof kind's largest displacement, each reaction and each member's largest
/// resultants; `governs` 1 on the combination that gives the quantity's largest value. Values
/// in `units` (each row names its unit).
CsvTable combinationsTable(const ResponseSpectrumResult& r, const Model& model,
                           const std::string& stem, const OutputUnits& units) {
  CsvTable t(stem + "_spectrum_combinations.csv",
             {{"combination", ""}, {"quantity", ""}, {"at", ""}, {"component", ""},
              {"unit", ""}, {"value", ""}, {"governs", ""}});
  const auto add = [&](const std::string& quantity, const std::string& at,
                       const std::string& component, const std::string& unit, auto read) {
    const OutputUnits::Shown shown = units.of(unit);
    const std::size_t governing = governingCombination(r, read);
    for (std::size_t i = 0; i < r.combinations.size(); ++i) {
      std::vector<CsvCell> row;  // filled in place: GCC 12 misreads a braced list of variants
      row.reserve(7);
      row.emplace_back(std::in_place_type<std::string>, r.combinations[i].name);
      row.emplace_back(std::in_place_type<std::string>, quantity);
      row.emplace_back(std::in_place_type<std::string>, at);
      row.emplace_back(std::in_place_type<std::string>, component);
      row.emplace_back(std::in_place_type<std::string>, shown.unit);
      row.emplace_back(std::in_place_type<double>, read(r.combinations[i].peak) * shown.factor);
      row.emplace_back(std::in_place_type<long long>, i == governing ? 1 : 0);
      t.addRow(std::move(row));
    }
  };
  for (int d = 0; d < 3; ++d)
    add("base_force", "", directionName(d), "N",
        [d](const PeakResponse& p) { return p.baseForce[std::size_t(d)]; });
  for (int k = 0; k < kDofKinds; ++k)
    add("largest_displacement", "", std::string(dofName(kAllDofs[k])), k < 3 ? "m" : "rad",
        [k](const PeakResponse& p) {
          return p.displacement.rows() > 0 ? p.displacement.col(k).maxCoeff() : 0.0;
        });
  const std::vector<ReactionComponent>& reactions = r.combined.reactions;
  for (std::size_t i = 0; i < reactions.size(); ++i)
    add("reaction", reactions[i].support, std::string(dofName(reactions[i].dof)),
        isRotation(reactions[i].dof) ? "N m" : "N",
        [i](const PeakResponse& p) { return p.reactions[i].value; });
  for (const auto& [name, elements] : model.members())
    for (ForceComponent c : kForceComponents) {
      const bool moment = c == ForceComponent::T || c == ForceComponent::My || c == ForceComponent::Mz;
      add("member", name, componentName(c), moment ? "N m" : "N",
          [&elements, c](const PeakResponse& p) { return memberPeak(p, elements, c); });
    }
  return t;
}

Json peakJson(const PeakResponse& p, const Model& model) {
  Json out = Json::object();
  Json base = Json::object();
  for (int d = 0; d < 3; ++d) base[directionName(d)] = p.baseForce[d];
  out["base_force_n"] = base;
  Json reactions = Json::array();
  for (const ReactionComponent& c : p.reactions)
    reactions.push_back({{"support", c.support}, {"dof", dofName(c.dof)}, {"value", c.value}});
  out["reactions"] = reactions;
  Json largest = Json::object();
  for (int k = 0; k < kDofKinds; ++k)
    largest[std::string(dofName(kAllDofs[k]))] =
        p.displacement.rows() > 0 ? p.displacement.col(k).maxCoeff() : 0.0;
  out["largest_displacement"] = largest;
  Json members = Json::object();
  for (const auto& [name, elements] : model.members()) {
    Json peaks = Json::object();
    for (ForceComponent c : kForceComponents) peaks[componentName(c)] = memberPeak(p, elements, c);
    members[name] = peaks;
  }
  if (!members.empty()) out["member_peaks"] = members;
  return out;
}

/// Sa against T as a gnuplot data block: over a table's own range, or an EN 1998-1 shape up to
/// 4 s (its range) or past the longest mode; its corners sampled exactly. A table's held end
/// values reach out to the modes beyond it. The spectrum's curve and the modes' (T, Sa), T shown
/// as `period` says and Sa as `sa`.
std::string spectrumCurve(const ResponseSpectrumResult& r, const OutputUnits::Shown& period,
                          const OutputUnits::Shown& sa) {
  std::vector<double> periods = r.spectrum.breakPeriods();
  double first = periods.front(), last = periods.back();
  if (!r.spectrum.isTable()) last = 4;
  for (const Mode& m : r.modal.modes) {
    if (!r.spectrum.isTable() || periodOf(m) > last) last = std::max(last, 1.1 * periodOf(m));
    if (r.spectrum.isTable()) first = std::min(first, periodOf(m));
  }
  if (first < periods.front()) periods.push_back(first);
  for (int i = 0; i <= 400; ++i) periods.push_back(first + (last - first) * i / 400.0);
  std::sort(periods.begin(), periods.end());
  std::ostringstream data;
  data << "$spectrum << EOD\n";
  for (double T : periods)
    if (T <= last)
      data << number(T * period.factor) << "," << number(r.spectrum.at(T) * sa.factor) << "\n";
  data << "EOD\n$modes << EOD\n";
  // Modes within 1 % of the axis of each other share one label ("1,2,3"), at the first.
  const std::size_t n = r.modal.modes.size();
  for (std::size_t j = 0; j < n;) {
    std::size_t end = j + 1;
    std::string label = std::to_string(j + 1);
    while (end < n &&
           std::abs(periodOf(r.modal.modes[end]) - periodOf(r.modal.modes[j])) < 0.01 * last) {
      label += ',';  // appended piece by piece: GCC 12 misreads "," + text
      label += std::to_string(end + 1);
      ++end;
    }
    for (std::size_t k = j; k < end; ++k)
      data << number(periodOf(r.modal.modes[k]) * period.factor) << ","
           << number(r.spectralAcceleration[k] * sa.factor) << ",\"" << (k == j ? label : "")
           << "\"\n";
    j = end;
  }
  data << "EOD\n";
  return data.str();
}

}  // namespace

std::string spectrumVtu(const std::string& stem) { return stem + "_spectrum.vtu"; }

double memberPeak(const PeakResponse& p, const std::vector<int>& elements, ForceComponent c) {
  double peak = 0;
  for (const BeamStation& s : p.stations)
    if (std::find(elements.begin(), elements.end(), s.element) != elements.end())
      peak = std::max(peak, componentOf(s.forces, c));
  return peak;
}

std::vector<CsvTable> spectrumTables(const ResponseSpectrumResult& r, const Model& model,
                                     const std::string& stem, const OutputUnits& units) {
  std::vector<CsvTable> tables{modesTable(r, stem), displacementsTable(r, model, stem)};
  if (!r.combined.reactions.empty()) tables.push_back(reactionsTable(r, stem, units));
  if (!r.combined.stations.empty()) tables.push_back(membersTable(r, model, stem));
  tables.push_back(combinationsTable(r, model, stem, units));
  return tables;
}

Json spectrumJson(const std::string& type, const std::string& name,
                  const ResponseSpectrumResult& r, const Model& model) {
  Json out = {{"type", type}, {"name", name}};
  out["spectrum"] = r.spectrum.describe();
  if (r.verticalSpectrum) out["vertical_spectrum"] = r.verticalSpectrum->describe();
  out["damping_ratio"] = r.dampingRatio;
  out["modal_combination"] = ruleName(r.rule);
  out["directional_combination"] = directionalName(r.directional);
  Json directions = Json::array();
  for (int d : r.directions) directions.push_back(directionName(d));
  out["directions"] = directions;
  Json modes = Json::array();
  for (std::size_t j = 0; j < r.modal.modes.size(); ++j) {
    const Mode& m = r.modal.modes[j];
    Json gamma = Json::object(), mass = Json::object();
    for (int d = 0; d < 3; ++d) {
      gamma[directionName(d)] = m.participation[d];
      mass[directionName(d)] = m.effectiveMass[d];
    }
    Json entry = {{"mode", j + 1},
                     {"frequency_hz", m.frequencyHz},
                     {"period_s", periodOf(m)},
                     {"sa_m_s2", r.spectralAcceleration[j]},
                     {"participation", gamma},
                     {"effective_mass_kg", mass},
                     {"description", m.description}};
    if (r.verticalSpectrum) entry["sa_vertical_m_s2"] = r.saOf(j, r.vertical);
    modes.push_back(entry);
  }
  out["modes"] = modes;
  Json total = Json::object(), captured = Json::object();
  const std::array<double, 3> fraction = r.capturedFraction();
  for (int d = 0; d < 3; ++d) {
    total[directionName(d)] = r.modal.totalMass[d];
    captured[directionName(d)] = fraction[d];
  }
  out["total_mass_kg"] = total;
  out["captured_mass_fraction"] = captured;
  Json each = Json::object();
  for (std::size_t i = 0; i < r.directions.size(); ++i)
    each[directionName(r.directions[i])] = peakJson(r.perDirection[i], model);
  out["per_direction"] = each;
  Json combinations = Json::array();
  for (const DirectionalCombination& c : r.combinations) {
    Json entry = peakJson(c.peak, model);
    entry["name"] = c.name;
    Json factors = Json::object();
    for (std::size_t i = 0; i < r.directions.size(); ++i)
      factors[directionName(r.directions[i])] = c.factors[i];
    entry["factors"] = factors;
    combinations.push_back(entry);
  }
  out["combinations"] = combinations;
  out["combined"] = peakJson(r.combined, model);
  // Which combination gives each combined reaction.
  for (std::size_t i = 0; i < r.combined.reactions.size(); ++i)
    out["combined"]["reactions"][i]["combination"] =
        r.combinations[governingCombination(r, [i](const PeakResponse& p) {
          return p.reactions[i].value;
        })].name;
  out["vtu"] = spectrumVtu(fileStem(name));
  return out;
}

void writeSpectrumFiles(const std::filesystem::path& dir, const ResponseSpectrumResult& r,
                        const Model& model, const std::string& stem, const std::string& caption,
                        bool charts, const OutputUnits& units) {
  writeFrameVtu(dir / spectrumVtu(stem), model, {0, r.combined.displacement});
  if (!charts) return;
  const OutputUnits::Shown period = units.of("s"), sa = units.of("m/s^2");
  std::ostringstream body;
  body << "  set encoding utf8\n"
       << "  set title " << captionText(caption + "\n" + r.spectrum.describe()) << "\n"
       << "  set grid\n"
       << "  set key top right\n"
       << "  set xlabel " << gnuplotText("period T [" + period.unit + "]") << "\n"
       << "  set ylabel " << gnuplotText("spectral acceleration Sa [" + sa.unit + "]") << "\n"
       << "  set xrange [0:*]\n  set yrange [0:*]\n"
       << "  plot $spectrum using 1:2 with lines linewidth 2 " << colour(0)
       << " title 'spectrum', \\\n"
       << "       $modes using 1:2 with points pointtype 7 pointsize 1.5 " << colour(1)
       << " title 'modes', \\\n"
       << "       $modes using 1:2:3 with labels offset 0,1 notitle\n";
  drawChart(dir, {stem + "_spectrum", "Response spectrum and the modes' periods", 900, 600,
                  body.str(), spectrumCurve(r, period, sa)});
}

}  // namespace beamrotor

// results.json entries of the rotor analyses (see RotorJson.hpp).
#include "problems/output/rotor/RotorJson.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>

#include "fem/rotor/RotorStability.hpp"
#include "problems/output/files/FileNames.hpp"
#include "problems/output/rotor/LevelOneOutput.hpp"
#include "problems/output/rotor/RunUpOutput.hpp"
#include "problems/output/rotor/RotorFileNames.hpp"
#include "problems/output/rotor/RotorTables.hpp"
#include "problems/output/rotor/UnwrappedPhase.hpp"

namespace beamrotor {

namespace {

/// A number, or null where it is infinite by definition (a real eigenvalue's decrement). A NaN
/// is a fault, not such a value: it stays a number for requireFiniteNumbers to refuse.
Json finiteOrNull(double x) {
  return std::isinf(x) ? Json(nullptr) : Json(x);
}

/// Which bearing coefficients the modes were found with (WhirlCoefficientsUsed).
Json coefficientsJson(const WhirlCoefficientsUsed& used, const std::vector<double>& speeds) {
  Json unsettled = Json::array();
  for (const auto& u : used.unsettled)
    unsettled.push_back({{"rpm", rpmOf(speeds.at(u.speed))}, {"frequency_hz", u.frequencyHz}});
  return {{"used", used.atOwnWhirl ? "each mode's eigenvalue" : "synchronous"},
          {"most_iterations", used.mostIterations},
          {"unsettled", unsettled}};
}

Json modesJson(const std::string& stem, const RotorModesResult& r) {
  Json frequencies = Json::array(), modes = Json::array(), vtus = Json::array(),
       orbits = Json::array();
  for (std::size_t m = 0; m < r.modes.size(); ++m) {
    const RotorMode& mode = r.modes[m];
    frequencies.push_back(mode.dampedFrequencyHz);
    modes.push_back({{"mode", m + 1},
                     {"frequency_hz", mode.dampedFrequencyHz},
                     {"natural_frequency_hz", mode.naturalFrequencyHz},
                     {"damping_ratio", mode.dampingRatio},
                     {"log_decrement", finiteOrNull(mode.logDecrement)},
                     {"whirl", std::string(whirlName(mode.whirl))},
                     {"whirl_ratio", mode.whirlRatio},
                     {"eigenvalue", {mode.eigenvalue.real(), mode.eigenvalue.imag()}},
                     {"whirl_iterations", mode.whirlIterations},
                     {"energy_in", energyIn(mode)},
                     {"bearing_energy", mode.bearingEnergy}});
    vtus.push_back(modeVtu(stem, int(m) + 1));
    orbits.push_back(orbitVtu(stem, int(m) + 1));
  }
  // The bearings' own modes (tilting pads kept as dofs), apart from the rotor's.
  Json padModes = Json::array();
  for (const RotorMode& mode : r.bearingModes)
    padModes.push_back({{"frequency_hz", mode.dampedFrequencyHz},
                        {"natural_frequency_hz", mode.naturalFrequencyHz},
                        {"damping_ratio", mode.dampingRatio},
                        {"log_decrement", finiteOrNull(mode.logDecrement)},
                        {"eigenvalue", {mode.eigenvalue.real(), mode.eigenvalue.imag()}},
                        {"energy_in", energyIn(mode)},
                        {"bearing_energy", mode.bearingEnergy}});
  return {{"speed_rpm", rpmOf(r.speed)},
          {"frequencies_hz", frequencies},
          {"modes", modes},
          {"pad_modes", padModes},
          {"bearing_coefficients", coefficientsJson(r.coefficients, {r.speed})},
          {"time_s", r.time.total},
          {"files",
           {{"modes_csv", modesCsv(stem)},
            {"pvd", collectionPvd(stem)},
            {"vtu", vtus},
            {"orbits_vtu", orbits},
            {"orbits_csv", orbitsCsv(stem)},
            {"orbits_chart", orbitsChart(stem) + ".svg"}}}};
}

Json campbellJson(const std::string& stem, const CampbellOutcome& r) {
  const CampbellResult& c = r.campbell;
  Json speeds = Json::array(), lines = Json::array(), critical = Json::array();
  for (double s : c.speeds) speeds.push_back(rpmOf(s));
  for (std::size_t l = 0; l < c.lines.size(); ++l) {
    Json f = Json::array(), zeta = Json::array(), delta = Json::array(), whirl = Json::array();
    for (const RotorMode& m : c.lines[l]) {
      f.push_back(m.dampedFrequencyHz);
      zeta.push_back(m.dampingRatio);
      delta.push_back(finiteOrNull(m.logDecrement));
      whirl.push_back(std::string(whirlName(m.whirl)));
    }
    lines.push_back({{"line", l + 1},
                     {"frequencies_hz", f},
                     {"damping_ratio", zeta},
                     {"log_decrement", delta},
                     {"whirl", whirl},
                     {"mac", c.mac[l]}});
  }
  const auto crossing = [](const CriticalSpeed& k) {
    return Json{{"rpm", k.rpm},
                {"speed_rad_s", k.speed},
                {"frequency_hz", k.frequencyHz},
                {"line", k.line + 1},
                {"damping_ratio", k.dampingRatio},
                {"whirl", std::string(whirlName(k.whirl))},
                {"order", k.order}};
  };
  for (const CriticalSpeed& k : r.criticalSpeeds) critical.push_back(crossing(k));
  // Further excitation orders: their crossings, apart from the critical speeds checks read.
  Json further = Json::array();
  for (double order : r.furtherOrders) {
    Json crossings = Json::array();
    for (const CriticalSpeed& k : r.furtherCriticalSpeeds)
      if (k.order == order) crossings.push_back(crossing(k));
    further.push_back({{"order", order}, {"crossings", crossings}});
  }
  // The least damped line's smallest log decrement over the sweep (what decides stability),
  // an undamped mode's round-off written 0 as the API 684 stability verdict reads it; null
  // for a mode that grows without oscillating (-inf).
  Json smallest = nullptr;
  if (const auto least = leastDamped(c))
    smallest = {{"value", finiteOrNull(least->logDecrement)},
                {"rpm", rpmOf(c.speeds[least->speed])},
                {"line", least->line + 1}};
  Json onset = nullptr;
  if (r.onset)
    onset = {{"rpm", r.onset->rpm},
             {"speed_rad_s", r.onset->speed},
             {"frequency_hz", r.onset->frequencyHz},
             {"whirl", std::string(whirlName(r.onset->whirl))},
             {"evaluations", r.onset->evaluations}};
  // The journal and tilting-pad bearings' operating points, as <stem>_bearings.csv has them.
  Json bearings = Json::object();
  for (const JournalBearingCurve& j : r.journals) {
    Json rpm = Json::array(), eps = Json::array(), attitude = Json::array();
    Json k = Json::object(), cc = Json::object();
    for (const char* name : {"kxx", "kxy", "kyx", "kyy"}) k[name] = Json::array();
    for (const char* name : {"cxx", "cxy", "cyx", "cyy"}) cc[name] = Json::array();
    for (std::size_t s = 0; s < j.speeds.size(); ++s) {
      rpm.push_back(rpmOf(j.speeds[s]));
      eps.push_back(j.eccentricity[s]);
      attitude.push_back(j.attitude[s] * 180 / std::numbers::pi);
      const BearingCoefficients& b = j.coefficients[s];
      k["kxx"].push_back(b.kyy);
      k["kxy"].push_back(b.kyz);
      k["kyx"].push_back(b.kzy);
      k["kyy"].push_back(b.kzz);
      cc["cxx"].push_back(b.cyy);
      cc["cxy"].push_back(b.cyz);
      cc["cyx"].push_back(b.czy);
      cc["cyy"].push_back(b.czz);
    }
    bearings[j.name] = {{"type", j.type},          {"speeds_rpm", rpm},
                        {"eccentricity", eps},     {"attitude_angle_deg", attitude},
                        {"stiffness_n_per_m", k}, {"damping_n_s_per_m", cc}};
  }
  return {{"order", r.order},
          {"speeds_rpm", speeds},
          {"bearings", bearings},
          {"instability_onset", onset},
          {"smallest_log_decrement", smallest},
          {"lines", lines},
          {"critical_speeds", critical},
          {"further_orders", further},
          {"symbolic_analyses", c.symbolicAnalyses},
          {"bearing_coefficients", coefficientsJson(c.coefficients, c.speeds)},
          {"time_s", c.time.total},
          {"files",
           {{"campbell_csv", campbellCsv(stem)},
            {"critical_speeds_csv", criticalSpeedsCsv(stem)},
            {"chart", campbellChart(stem) + ".svg"},
            {"stability_chart", stabilityChart(stem) + ".svg"}}}};
}

/// API 684 reading: the operating range and each response point's peaks.
Json api684Json(const std::string& stem, const UnbalanceOutcome& r) {
  Json points = Json::object();
  for (std::size_t k = 0; k < r.peaks.size(); ++k) {
    Json peaks = Json::array();
    for (const ResponsePeak& p : r.peaks[k]) {
      peaks.push_back({{"rpm", rpmOf(p.speed)},
                       {"amplitude_m", p.amplitude},
                       {"half_power_rpm", {rpmOf(p.lowerHalfPower), rpmOf(p.upperHalfPower)}},
                       {"amplification_factor", p.amplificationFactor},
                       {"amplification_method", amplificationMethodName(p.method)},
                       {"modal_damping_ratio", p.dampingRatio},
                       {"overlapping", p.overlapping},
                       {"required_margin_percent", p.requiredMargin},
                       {"actual_margin_percent", p.actualMargin},
                       {"pass", p.pass}});
    }
    points[r.responsePoints[k]] = peaks;
  }
  Json stability(nullptr);
  if (r.stability) {
    const OperatingStability& s = *r.stability;
    stability = {{"min_log_decrement_required", s.required},
                 {"smallest_log_decrement", finiteOrNull(s.smallest)},
                 {"at_rpm", rpmOf(s.speed)},
                 {"frequency_hz", s.frequencyHz},
                 {"whirl", std::string(whirlName(s.whirl))},
                 {"onset_rpm", s.onset ? Json(s.onset->rpm) : Json(nullptr)},
                 {"pass", s.pass}};
  }
  return {{"operating_rpm", {rpmOf(r.operating->minimum), rpmOf(r.operating->maximum)}},
          {"peaks", points},
          {"stability", stability},
          {"pass", r.api684Pass()},
          {"csv", api684Csv(stem)}};
}

Json unbalanceJson(const std::string& stem, const UnbalanceOutcome& r) {
  const UnbalanceResult& u = r.unbalance;
  Json speeds = Json::array(), response = Json::object();
  for (double s : u.speeds) speeds.push_back(rpmOf(s));
  for (std::size_t k = 0; k < r.responsePoints.size(); ++k) {
    Json major = Json::array(), ay = Json::array(), az = Json::array(), py = Json::array(),
         pz = Json::array();
    std::size_t peak = 0;
    const UnbalancePhases phases = unbalancePhases(u.orbits[k]);
    for (std::size_t s = 0; s < u.speeds.size(); ++s) {
      const Orbit& o = u.orbits[k][s];
      major.push_back(o.major());
      ay.push_back(std::abs(o.uy));
      az.push_back(std::abs(o.uz));
      py.push_back(phases.uy[s]);
      pz.push_back(phases.uz[s]);
      if (o.major() > u.orbits[k][peak].major()) peak = s;
    }
    response[r.responsePoints[k]] = {
        {"amplitude_m", major},
        {"uy_amplitude_m", ay},
        {"uz_amplitude_m", az},
        {"uy_phase_deg", py},
        {"uz_phase_deg", pz},
        {"peak", {{"amplitude_m", u.orbits[k][peak].major()}, {"rpm", rpmOf(u.speeds[peak])}}}};
  }
  return {
      {"speeds_rpm", speeds},
      {"response", response},
      {"api684", r.operating ? api684Json(stem, r) : Json(nullptr)},
      {"time_s", u.time.total},
      {"files", {{"unbalance_csv", unbalanceCsv(stem)}, {"chart", unbalanceChart(stem) + ".svg"}}}};
}

Json frequencyResponseJson(const std::string& stem, const FrequencyResponseOutcome& r) {
  const FrequencyResponseResult& f = r.response;
  Json hz = Json::array(), magnitude = Json::array();
  for (std::size_t i = 0; i < f.frequencies.size(); ++i) {
    hz.push_back(f.frequencies[i] / (2 * std::numbers::pi));
    magnitude.push_back(std::abs(f.receptance[i]));
  }
  const Json phase = unwrappedPhases(f.receptance);
  return {{"speed_rpm", rpmOf(f.speed)},
          {"input", r.input},
          {"output", r.output},
          {"frequencies_hz", hz},
          {"magnitude", magnitude},
          {"phase_deg", phase},
          {"time_s", f.time.total},
          {"files",
           {{"frf_csv", frequencyResponseCsv(stem)},
            {"chart", frequencyResponseChart(stem) + ".svg"}}}};
}

Json criticalSpeedMapJson(const std::string& stem, const CriticalSpeedMapOutcome& r) {
  const CriticalSpeedMap& m = r.map;
  const auto rpms = [](const std::vector<double>& speeds) {
    Json out = Json::array();
    for (double s : speeds) out.push_back(rpmOf(s));
    return out;
  };
  Json stiffness = Json::array(), speeds = Json::array(), bearings = Json::array();
  for (std::size_t i = 0; i < m.stiffness.size(); ++i) {
    stiffness.push_back(m.stiffness[i]);
    speeds.push_back(rpms(m.speeds[i]));
  }
  const auto crossings = [](const std::vector<MapCrossing>& list) {
    Json out = Json::array();
    for (const MapCrossing& c : list)
      out.push_back({{"critical_speed", c.line + 1}, {"rpm", rpmOf(c.speed)}, {"stiffness", c.stiffness}});
    return out;
  };
  for (const BearingStiffnessCurve& b : r.bearings)
    bearings.push_back({{"bearing", b.name},
                        {"speeds_rpm", rpms(b.speeds)},
                        {"kxx", b.kxx},
                        {"kyy", b.kyy},
                        {"kxx_crossings", crossings(b.kxxCrossings)},
                        {"kyy_crossings", crossings(b.kyyCrossings)}});
  Json files = {{"map_csv", criticalSpeedMapCsv(stem)},
                {"chart", criticalSpeedMapChart(stem) + ".svg"}};
  if (!r.bearings.empty()) {
    files["bearings_csv"] = mapBearingsCsv(stem);
    files["crossings_csv"] = mapCrossingsCsv(stem);
  }
  return {{"whirl", "non-rotating (gyroscopic moments neglected)"},
          {"stiffness", stiffness},
          {"critical_speeds_rpm", speeds},
          {"pinned_rpm", rpms(m.pinned)},
          {"free_free_rpm", rpms(m.freeFree)},
          {"bearings", bearings},
          {"time_s", r.time},
          {"files", files}};
}

Json bearingLoadsJson(const std::string& stem, const BearingLoadsOutcome& r) {
  const GravityLoads& g = r.loads;
  Json bearings = Json::object();
  for (std::size_t i = 0; i < g.bearings.size(); ++i) {
    const BearingForce& b = g.bearings[i];
    bearings[r.bearingNames.at(i)] = {
        {"x", b.x}, {"fy", b.fy}, {"fz", b.fz}, {"load", std::hypot(b.fy, b.fz)}};
  }
  const int worst = g.largestSag();
  const bool any = worst >= 0;
  return {{"bearing_support", r.rigidBearings ? "rigid" : "elastic"},
          {"weight", {g.weight.x(), g.weight.y(), g.weight.z()}},
          {"bearings", bearings},
          {"largest_sag",
           {{"x", any ? g.x[worst] : 0.0},
            {"uy", any ? g.uy[worst] : 0.0},
            {"uz", any ? g.uz[worst] : 0.0},
            {"magnitude", any ? std::hypot(g.uy[worst], g.uz[worst]) : 0.0}}},
          {"time_s", r.time},
          {"files", {{"bearing_loads_csv", bearingLoadsCsv(stem)}, {"sag_csv", sagCsv(stem)}}}};
}

Json levelOneJson(const std::string& stem, const LevelOneOutcome& o) {
  const LevelOneResult& r = o.screening;
  Json curve = Json::array();
  for (const CrossCouplingSample& s : r.curve)
    curve.push_back({{"q", s.crossCoupling}, {"log_decrement", finiteOrNull(s.logDecrement)}});
  return {{"speed_rpm", r.speed * 30 / std::numbers::pi},
          {"station", o.station},
          {"stages", o.stages},
          {"qa", r.anticipated},
          {"q0", r.found ? Json(r.zeroDecrement) : Json(nullptr)},
          {"q0_found", r.found},
          {"q0_over_qa", finiteOrNull(r.ratio)},
          {"log_decrement_without", finiteOrNull(r.baseLogDecrement)},
          {"log_decrement_at_qa", finiteOrNull(r.logDecrementAtQa)},
          {"frequency_hz_at_qa", r.frequencyHzAtQa},
          {"least_damped_at_qa", r.bearingModeAtQa ? "pads" : "rotor"},
          {"frequency_hz_at_q0", r.frequencyHzAtQ0},
          {"whirl_at_q0", std::string(whirlName(r.whirlAtQ0))},
          {"least_damped_at_q0", r.bearingModeAtQ0 ? "pads" : "rotor"},
          {"evaluations", r.evaluations},
          {"map_decides", r.mapDecides},
          {"csr_map",
           {{"max_continuous_rpm", r.map.maximumContinuousSpeed * 30 / std::numbers::pi},
            {"rigid_critical_rpm", r.map.rigidCriticalSpeed * 30 / std::numbers::pi},
            {"critical_speed_ratio", r.map.ratio},
            {"average_gas_density", r.map.averageDensity},
            {"boundary", r.map.boundary},
            {"region", r.map.regionB ? "B" : "A"}}},
          {"pass", r.pass},
          {"verdict", levelOneVerdict(r)},
          {"curve", curve},
          {"time_s", o.time},
          {"files", {{"level1_csv", levelOneCsv(stem)}}}};
}

Json runUpJson(const std::string& stem, const RunUpOutcome& o) {
  const RunUpResult& r = o.runUp;
  Json points = Json::array();
  for (std::size_t k = 0; k < o.responsePoints.size(); ++k) {
    const RunUpHistory& h = r.histories[k];
    const bool any = !h.revolutions.amplitude.empty();
    points.push_back({{"point", o.responsePoints[k]},
                      {"peak_amplitude", any ? Json(h.peakAmplitude) : Json(nullptr)},
                      {"speed_at_peak_rpm", any ? Json(h.speedAtPeak * 30 / std::numbers::pi)
                                                : Json(nullptr)},
                      {"time_at_peak", any ? Json(h.timeAtPeak) : Json(nullptr)}});
  }
  Json journals = Json::array();
  for (const JournalTrack& j : r.journals) {
    // A tilting-pad film's pads: each tilt's range over the samples (rad).
    Json pads = Json::array();
    for (std::size_t k = 0; k < j.ownNames.size(); ++k)
      if (const auto range = j.ownRange(k))
        pads.push_back({{"name", j.ownNames[k]},
                        {"start", j.own[k].front()},
                        {"min", range->first},
                        {"max", range->second},
                        {"end", j.own[k].back()}});
    journals.push_back({{"bearing", j.name},
                        {"clearance", j.clearance},
                        {"start_eccentricity", j.startEccentricity},
                        {"largest_eccentricity", j.largestEccentricity},
                        {"pad_tilts", pads}});
  }
  Json rubs = Json::array();
  for (std::size_t k = 0; k < r.rubs.size(); ++k) {
    const RubTrack& t = r.rubs[k];
    rubs.push_back({{"name", t.name},
                    {"point", o.rubPoints[k]},
                    {"clearance", t.clearance},
                    {"contact_time", t.contactTime},
                    {"first_contact", t.firstContact < 0 ? Json(nullptr) : Json(t.firstContact)},
                    {"peak_normal_force", t.peakNormal},
                    {"peak_rub_torque", t.peakTorque},
                    {"friction_work", t.frictionWork},
                    {"contact_damping_work", t.dampingWork}});
  }
  const RunUpEnergy& e = r.energy;
  const std::size_t last = e.kinetic.empty() ? 0 : e.kinetic.size() - 1;
  const double rpm = 30 / std::numbers::pi;
  return {{"start_rpm", r.speed.empty() ? 0.0 : r.speed.front() * rpm},
          {"end_rpm", r.speed.empty() ? 0.0 : r.speed.back() * rpm},
          {"duration_s", r.times.empty() ? 0.0 : r.times.back()},
          {"dt", r.timeStep},
          {"steps", r.steps},
          {"scheme", o.alpha == 0 ? "newmark" : "hht"},
          {"alpha", o.alpha},
          {"start", o.steadyStart ? "steady" : "rest"},
          {"revolutions", r.histories.empty() ? 0 : r.histories[0].revolutions.speed.size()},
          {"factorizations", r.factorizations},
          {"speed_driven", r.driven},
          {"polar_inertia", o.inertia},
          {"bearings", r.journals.empty() ? "linear" : "nonlinear"},
          {"newton_iterations", r.newtonIterations},
          {"most_newton_iterations", r.mostNewtonIterations},
          {"journals", journals},
          {"end_film_torque", r.filmTorque.empty() ? Json(nullptr) : Json(r.filmTorque.back())},
          {"rubs", rubs},
          {"points", points},
          {"energy",
           {{"kinetic", e.kinetic.empty() ? 0.0 : e.kinetic[last]},
            {"strain", e.strain.empty() ? 0.0 : e.strain[last]},
            {"dissipated", e.dissipated.empty() ? 0.0 : e.dissipated[last]},
            {"gyroscopic", e.gyroscopic.empty() ? 0.0 : e.gyroscopic[last]},
            {"film", e.film.empty() ? 0.0 : e.film[last]},
            {"rub", e.rub.empty() ? 0.0 : e.rub[last]},
            {"work", e.work.empty() ? 0.0 : e.work[last]},
            {"balance", e.kinetic.empty() ? 0.0 : e.balance(last)}}},
          {"time_s", r.time.total},
          {"files",
           {{"runup_csv", runUpCsv(stem)}, {"runup_history_csv", runUpHistoryCsv(stem)}}}};
}

Json rigidBodyJson(const RigidBodyOutcome& r) {
  const FormeShaftRigid& s = r.rigid;
  Json modes = Json::array();
  for (std::size_t i = 0; i < r.modes.size(); ++i) {
    const FormeShaftMode& m = r.modes[i];
    modes.push_back({{"mode", i + 1},
                     {"paper_name", std::string(paperModeName(int(i)))},
                     {"frequency_hz", m.k / (2 * std::numbers::pi)},
                     {"k_rad_s", m.k},
                     {"kind", std::string(formeModeKindName(m.kind))},
                     {"z", m.z},
                     {"phi", m.phi},
                     {"n", finiteOrNull(m.n)},
                     {"FA", m.FA},
                     {"FB", m.FB},
                     {"inertia_force", m.inertiaForce},
                     {"inertia_moment", m.inertiaMoment}});
  }
  return {{"rigid_body",
           {{"mass", r.body.m},
            {"com_x", r.body.xG},
            {"J_com", r.body.J},
            {"Jp", r.body.Jp},
            {"bearing_x", {{r.points[0], r.x[0]}, {r.points[1], r.x[1]}}},
            {"stiffness", {{r.points[0], r.stiffness[0]}, {r.points[1], r.stiffness[1]}}}}},
          {"two_dof",
           {{"l1", s.l1},
            {"l2", s.l2},
            {"a", s.a()},
            {"b", s.b()},
            {"d", s.d()},
            {"rho2", s.rho2()},
            {"decoupled", r.modes[0].kind != FormeModeKind::coupled},
            {"modes", modes}}}};
}

/// The analysis' entry: its type and name first, then what its kind writes.
Json entry(const AnalysisOutcome& a, const Json& body) {
  Json out = {{"type", a.type}, {"name", a.name}};
  for (const auto& [key, value] : body.items()) out[key] = value;
  return out;
}

}  // namespace

Json rotorJson(const AnalysisOutcome& a, const RotorModesResult& r) {
  return entry(a, modesJson(fileStem(a.name), r));
}
Json rotorJson(const AnalysisOutcome& a, const CampbellOutcome& r) {
  return entry(a, campbellJson(fileStem(a.name), r));
}
Json rotorJson(const AnalysisOutcome& a, const UnbalanceOutcome& r) {
  return entry(a, unbalanceJson(fileStem(a.name), r));
}
Json rotorJson(const AnalysisOutcome& a, const RigidBodyOutcome& r) {
  return entry(a, rigidBodyJson(r));
}
Json rotorJson(const AnalysisOutcome& a, const FrequencyResponseOutcome& r) {
  return entry(a, frequencyResponseJson(fileStem(a.name), r));
}
Json rotorJson(const AnalysisOutcome& a, const CriticalSpeedMapOutcome& r) {
  return entry(a, criticalSpeedMapJson(fileStem(a.name), r));
}
Json rotorJson(const AnalysisOutcome& a, const BearingLoadsOutcome& r) {
  return entry(a, bearingLoadsJson(fileStem(a.name), r));
}
Json rotorJson(const AnalysisOutcome& a, const LevelOneOutcome& r) {
  return entry(a, levelOneJson(fileStem(a.name), r));
}

Json rotorJson(const AnalysisOutcome& a, const RunUpOutcome& r) {
  return entry(a, runUpJson(fileStem(a.name), r));
}

}  // namespace beamrotor

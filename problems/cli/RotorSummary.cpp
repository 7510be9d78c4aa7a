// Summary lines of the rotor analyses (see RotorSummary.hpp).
#include "problems/cli/RotorSummary.hpp"

#include <cmath>
#include <numbers>
#include <string>
#include <utility>
#include <vector>

#include "fem/rotor/RotorStability.hpp"
#include "problems/cli/Summary.hpp"
#include "problems/output/rotor/LevelOneOutput.hpp"

namespace beamrotor::cli {

namespace {

constexpr double kRpm = 30 / std::numbers::pi;

/// The stability half of the API 684 verdict.
void printOperatingStability(std::ostream& out, const OperatingStability& s) {
  out << "      stability: smallest log decrement in the range " << formatValue(s.smallest)
      << " at " << formatValue(s.speed * kRpm) << " rpm (" << formatValue(s.frequencyHz) << " Hz "
      << whirlName(s.whirl) << " whirl; required " << formatValue(s.required) << ")";
  if (s.onset)
    out << ", UNSTABLE above " << formatValue(s.onset->rpm) << " rpm ("
        << formatValue(s.onset->frequencyHz) << " Hz " << whirlName(s.onset->whirl) << " whirl)";
  else if (s.smallest < 0)
    out << ", unstable from the sweep's first speed";
  out << ": " << (s.pass ? "pass" : "FAIL") << "\n";
}

/// The API 684 verdict as a whole, PASS or FAIL, with what fails it.
void printApi684Verdict(std::ostream& out, const UnbalanceOutcome& r) {
  if (r.api684Pass()) {
    out << "      API 684: PASS (every peak's separation margin";
    if (r.stability)
      out << ", log decrement at least " << formatValue(r.stability->required)
          << " over the operating range";
    out << ")\n";
    return;
  }
  std::vector<std::string> reasons;
  for (std::size_t k = 0; k < r.peaks.size(); ++k)
    for (const ResponsePeak& p : r.peaks[k])
      if (!p.pass) {
        std::string reason = r.responsePoints[k];
        reason += ": peak at ";
        reason += formatValue(p.speed * kRpm);
        reason += " rpm";
        reasons.push_back(reason);
      }
  if (r.stability && !r.stability->pass) {
    const OperatingStability& s = *r.stability;
    std::string reason;
    if (s.onset && s.onset->speed <= r.operating->maximum) {
      reason += "unstable above ";
      reason += formatValue(s.onset->rpm);
      reason += " rpm, ";
    }
    reason += "log decrement ";
    reason += formatValue(s.smallest);
    reason += " in the operating range";
    reasons.push_back(reason);
  }
  out << "      API 684: FAIL (";
  for (std::size_t i = 0; i < reasons.size(); ++i) out << (i ? "; " : "") << reasons[i];
  out << ")\n";
}

/// What a two-dof mode is, in words: coupled, or (b = 0) the limits of the paper's 0/0 ratio.
std::string modeShapeText(const FormeShaftMode& m) {
  switch (m.kind) {
    case FormeModeKind::bounce:
      return "pure bounce (phi = 0: C1 l1 = C2 l2, the paper's n = 0/0 tends to infinity)";
    case FormeModeKind::rocking:
      return "pure rocking about the centre of mass (z = 0, n = 0)";
    default:
      return "n = " + formatValue(m.n) + " m/rad";
  }
}

}  // namespace

void printRotor(std::ostream& out, const AnalysisOutcome& a, const RotorModesResult& r) {
  out << "rotor analysis '" << a.name << "' at " << formatValue(r.speed * kRpm) << " rpm ("
      << r.modes.size() << " damped modes)\n";
  for (std::size_t i = 0; i < r.modes.size(); ++i) {
    const RotorMode& m = r.modes[i];
    out << "    mode " << i + 1 << "  " << formatValue(m.dampedFrequencyHz) << " Hz  damping "
        << formatValue(m.dampingRatio) << "  log decrement "
        << (std::isfinite(m.logDecrement) ? formatValue(m.logDecrement) : std::string("inf"))
        << "  " << whirlName(m.whirl) << "\n";
  }
}

void printRotor(std::ostream& out, const AnalysisOutcome& a, const CampbellOutcome& r) {
  const CampbellResult& c = r.campbell;
  out << "campbell analysis '" << a.name << "' (" << c.lines.size() << " lines, " << c.speeds.size()
      << " speeds " << formatValue(c.speeds.front() * kRpm) << " to "
      << formatValue(c.speeds.back() * kRpm) << " rpm)\n";
  if (r.criticalSpeeds.empty())
    out << "    no critical speed (" << formatValue(r.order) << "x) in this range\n";
  // Numbered as the check quantity `critical_speed N` reads them.
  for (std::size_t i = 0; i < r.criticalSpeeds.size(); ++i) {
    const CriticalSpeed& k = r.criticalSpeeds[i];
    out << "    critical speed " << i + 1 << ": " << formatValue(k.rpm) << " rpm ("
        << formatValue(k.frequencyHz) << " Hz, line " << k.line + 1 << ", "
        << whirlName(k.whirl) << " whirl)\n";
  }
  for (const CriticalSpeed& k : r.furtherCriticalSpeeds)
    out << "    " << formatValue(k.order) << "x speed meets line " << k.line + 1 << " at "
        << formatValue(k.rpm) << " rpm (" << formatValue(k.frequencyHz) << " Hz, "
        << whirlName(k.whirl) << " whirl)\n";
  // The least damped line: its smallest log decrement over the sweep.
  if (const auto least = leastDamped(c))
    out << "    smallest log decrement " << formatValue(least->logDecrement) << " (line "
        << least->line + 1 << " at " << formatValue(c.speeds[least->speed] * kRpm) << " rpm)\n";
  if (r.onset)
    out << "    UNSTABLE above " << formatValue(r.onset->rpm) << " rpm (onset of instability: "
        << formatValue(r.onset->frequencyHz) << " Hz " << whirlName(r.onset->whirl) << " whirl)\n";
  else
    out << "    stable over the sweep (no log decrement falls through zero)\n";
}

void printRotor(std::ostream& out, const AnalysisOutcome& a, const UnbalanceOutcome& r) {
  const UnbalanceResult& u = r.unbalance;
  out << "unbalance analysis '" << a.name << "' (" << u.speeds.size() << " speeds)\n";
  for (std::size_t k = 0; k < r.responsePoints.size(); ++k) {
    std::size_t peak = 0;
    for (std::size_t s = 0; s < u.speeds.size(); ++s)
      if (u.orbits[k][s].major() > u.orbits[k][peak].major()) peak = s;
    out << "    " << r.responsePoints[k] << ": largest orbit "
        << formatValue(u.orbits[k][peak].major()) << " m at " << formatValue(u.speeds[peak] * kRpm)
        << " rpm\n";
  }
  if (!r.operating) return;
  out << "    API 684, operating range " << formatValue(r.operating->minimum * kRpm) << " to "
      << formatValue(r.operating->maximum * kRpm) << " rpm:\n";
  for (std::size_t k = 0; k < r.peaks.size(); ++k)
    for (const ResponsePeak& p : r.peaks[k]) {
      out << "      " << r.responsePoints[k] << ": peak " << formatValue(p.amplitude) << " m at "
          << formatValue(p.speed * kRpm) << " rpm, ";
      if (p.method == AmplificationMethod::none) {
        out << "no half-power points (the orbit does not fall to peak / sqrt(2) on both sides: "
               "a neighbouring peak or the sweep's end): AF unknown, FAIL\n";
        continue;
      }
      out << "AF " << formatValue(p.amplificationFactor);
      if (p.method == AmplificationMethod::modalDamping)
        out << " (1 / (2 zeta), zeta " << formatValue(p.dampingRatio) << " of the mode: "
            << (p.overlapping ? "overlapping peaks" : "no half-power points") << ")";
      out << ", margin " << formatValue(p.actualMargin)
          << " % (required " << formatValue(p.requiredMargin) << " %): "
          << (p.pass ? "pass" : "FAIL") << "\n";
    }
  if (r.stability) printOperatingStability(out, *r.stability);
  printApi684Verdict(out, r);
}

void printRotor(std::ostream& out, const AnalysisOutcome& a, const RigidBodyOutcome& r) {
  out << "rigid-body analysis '" << a.name << "': m = " << formatValue(r.body.m)
      << " kg, centre of mass x = " << formatValue(r.body.xG) << " m, J = " << formatValue(r.body.J)
      << " kg m^2 (mode amplitudes scaled to z^2 + rho^2 phi^2 = 1 m^2; bearing loads scale"
         " with the amplitude)\n";
  for (std::size_t i = 0; i < r.modes.size(); ++i) {
    const FormeShaftMode& m = r.modes[i];
    out << "    two-dof mode " << i + 1 << " (the paper's " << paperModeName(int(i)) << ")  "
        << formatValue(m.k / (2 * std::numbers::pi)) << " Hz (k = " << formatValue(m.k)
        << " rad/s)  " << modeShapeText(m) << "  F_" << r.points[0] << " = " << formatValue(m.FA)
        << " N, F_" << r.points[1] << " = " << formatValue(m.FB)
        << " N per metre of modal amplitude\n";
  }
}

void printRotor(std::ostream& out, const AnalysisOutcome& a, const FrequencyResponseOutcome& r) {
  const FrequencyResponseResult& f = r.response;
  std::size_t peak = 0;
  for (std::size_t i = 0; i < f.receptance.size(); ++i)
    if (std::abs(f.receptance[i]) > std::abs(f.receptance[peak])) peak = i;
  out << "frequency-response analysis '" << a.name << "' at " << formatValue(f.speed * kRpm)
      << " rpm: " << r.output << " / " << r.input << ", " << f.frequencies.size()
      << " frequencies\n";
  if (!f.receptance.empty())
    out << "    largest receptance " << formatValue(std::abs(f.receptance[peak])) << " at "
        << formatValue(f.frequencies[peak] / (2 * std::numbers::pi)) << " Hz\n";
}

void printRotor(std::ostream& out, const AnalysisOutcome& a, const CriticalSpeedMapOutcome& r) {
  const CriticalSpeedMap& m = r.map;
  out << "critical-speed-map analysis '" << a.name << "' (" << m.stiffness.size()
      << " bearing stiffnesses " << formatValue(m.stiffness.front()) << " to "
      << formatValue(m.stiffness.back()) << " N/m, gyroscopic moments neglected, "
      << formatValue(r.time) << " s)\n";
  const auto list = [&](const char* what, const std::vector<double>& speeds) {
    out << "    " << what;
    for (double s : speeds) out << " " << formatValue(s * kRpm);
    out << " rpm\n";
  };
  list("pinned bearings:", m.pinned);
  list("free-free rotor:", m.freeFree);
  for (const BearingStiffnessCurve& b : r.bearings)
    for (const auto& [what, crossings] :
         {std::pair{"kxx", &b.kxxCrossings}, std::pair{"kyy", &b.kyyCrossings}}) {
      out << "    bearing " << b.name << " " << what << " meets the map at";
      if (crossings->empty()) out << " no critical speed in range";
      for (const MapCrossing& c : *crossings)
        out << " " << formatValue(c.speed * kRpm) << " rpm (critical speed " << c.line + 1
            << ")";
      out << "\n";
    }
}

void printRotor(std::ostream& out, const AnalysisOutcome& a, const BearingLoadsOutcome& r) {
  const GravityLoads& g = r.loads;
  out << "bearing-loads analysis '" << a.name << "' (" << (r.rigidBearings ? "pinned" : "elastic")
      << " bearings, weight " << formatValue(g.weight.norm()) << " N)\n";
  for (std::size_t i = 0; i < g.bearings.size(); ++i) {
    const BearingForce& b = g.bearings[i];
    out << "    bearing " << r.bearingNames.at(i) << " at x = " << formatValue(b.x)
        << " m carries " << formatValue(std::hypot(b.fy, b.fz)) << " N (fy " << formatValue(b.fy)
        << ", fz " << formatValue(b.fz) << " N on the shaft)\n";
  }
  const int worst = g.largestSag();
  if (worst >= 0)
    out << "    largest sag " << formatValue(std::hypot(g.uy[worst], g.uz[worst])) << " m at x = "
        << formatValue(g.x[worst]) << " m\n";
}

void printRotor(std::ostream& out, const AnalysisOutcome& a, const LevelOneOutcome& o) {
  const LevelOneResult& r = o.screening;
  out << "level1-stability analysis '" << a.name << "' at " << formatValue(r.speed * kRpm)
      << " rpm, cross-coupling at " << o.station << " (" << formatValue(o.time) << " s)\n"
      << "    Qa " << formatValue(r.anticipated) << " N/m from " << o.stages
      << " stage(s) (API 617); least log decrement " << formatValue(r.baseLogDecrement)
      << " without, " << formatValue(r.logDecrementAtQa) << " at Qa ("
      << formatValue(r.frequencyHzAtQa) << " Hz)\n";
  if (r.found)
    out << "    Q0 " << formatValue(r.zeroDecrement) << " N/m (" << whirlName(r.whirlAtQ0)
        << " whirl at " << formatValue(r.frequencyHzAtQ0) << " Hz), Q0/Qa "
        << formatValue(r.ratio) << "\n";
  else
    out << "    Q0 not found: no cross-coupling up to 2^40 Qa destabilises the rotor\n";
  out << "    API 684 Level I: " << levelOneVerdict(r) << "\n";
}

}  // namespace beamrotor::cli

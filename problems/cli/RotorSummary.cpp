// Summary lines of the rotor analyses (see RotorSummary.hpp).
#include "problems/cli/RotorSummary.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <string>
#include <utility>
#include <vector>

#include "fem/rotor/RotorStability.hpp"
#include "problems/cli/Summary.hpp"
#include "problems/output/rotor/LevelOneOutput.hpp"
#include "problems/output/structure/NoiseFloor.hpp"

namespace beamrotor::cli {

namespace {

constexpr double kRpm = 30 / std::numbers::pi;

/// "3000 rpm", or in the user's speed unit.
std::string rpmText(double rpm, const OutputUnits& units) {
  return valueText(rpm, "rpm", units);
}

/// "12.5 Hz", or in the user's frequency unit.
std::string hzText(double hz, const OutputUnits& units) {
  return valueText(hz, "Hz", units);
}

/// The stability half of the API 684 verdict.
void printOperatingStability(std::ostream& out, const OperatingStability& s,
                             const OutputUnits& units) {
  out << "      stability: smallest log decrement in the range " << formatValue(s.smallest)
      << " at " << rpmText(s.speed * kRpm, units) << " (" << hzText(s.frequencyHz, units) << " "
      << whirlName(s.whirl) << " whirl; required " << formatValue(s.required) << ")";
  if (s.onset)
    out << ", UNSTABLE above " << rpmText(s.onset->rpm, units) << " ("
        << hzText(s.onset->frequencyHz, units) << " " << whirlName(s.onset->whirl) << " whirl)";
  else if (s.smallest < 0)
    out << ", unstable from the sweep's first speed";
  out << ": " << (s.pass ? "pass" : "FAIL") << "\n";
}

/// The API 684 verdict as a whole, PASS or FAIL, with what fails it.
void printApi684Verdict(std::ostream& out, const UnbalanceOutcome& r, const OutputUnits& units) {
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
        reason += rpmText(p.speed * kRpm, units);
        reasons.push_back(reason);
      }
  if (r.stability && !r.stability->pass) {
    const OperatingStability& s = *r.stability;
    std::string reason;
    if (s.onset && s.onset->speed <= r.operating->maximum) {
      reason += "unstable above ";
      reason += rpmText(s.onset->rpm, units);
      reason += ", ";
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

/// What a two-dof mode is, in words: coupled (n in `units`' length per angle), or (b = 0) the
/// limits of the paper's 0/0 ratio.
std::string modeShapeText(const FormeShaftMode& m, const OutputUnits& units) {
  switch (m.kind) {
    case FormeModeKind::bounce:
      return "pure bounce (phi = 0: C1 l1 = C2 l2, the paper's n = 0/0 tends to infinity)";
    case FormeModeKind::rocking:
      return "pure rocking about the centre of mass (z = 0, n = 0)";
    default: {
      const OutputUnits::Shown length = units.valueIn("m", {1, "m"});
      const OutputUnits::Shown angle = units.valueIn("rad", {1, "rad"});
      std::string text = "n = ";  // appended piece by piece: GCC 12's false -Wrestrict
      text += formatValue(m.n * length.factor / angle.factor);
      text += " ";
      text += length.unit;
      text += "/";
      text += angle.unit;
      return text;
    }
  }
}

/// Which bearing coefficients the modes saw, for whirl-dependent bearings (the synchronous
/// set, the only one of other bearings, goes unsaid).
void printCoefficientsUsed(std::ostream& out, const WhirlCoefficientsUsed& used) {
  if (!used.atOwnWhirl) return;
  out << "    bearing coefficients: each mode's own, at its eigenvalue (whirl-dependent "
         "bearings; at most "
      << used.mostIterations << " eigen-solutions a mode";
  if (!used.unsettled.empty()) out << "; " << used.unsettled.size() << " did not settle";
  out << ")\n";
}

}  // namespace

void printRotor(std::ostream& out, const AnalysisOutcome& a, const RotorModesResult& r,
                const OutputUnits& units) {
  out << "rotor analysis '" << a.name << "' at " << rpmText(r.speed * kRpm, units) << " ("
      << r.modes.size() << " damped modes)\n";
  printCoefficientsUsed(out, r.coefficients);
  for (std::size_t i = 0; i < r.modes.size(); ++i) {
    const RotorMode& m = r.modes[i];
    // Damping within what the eigensolver's round-off gives in either sign is neutral: 0, not
    // +-1e-16 (an undamped rotor's modes), whose sign would read as a verdict.
    const bool neutral = std::abs(m.dampingRatio) <= m.roundOff;
    out << "    mode " << i + 1 << "  " << hzText(m.dampedFrequencyHz, units) << "  damping "
        << formatValue(neutral ? 0.0 : m.dampingRatio) << "  log decrement "
        << (neutral                         ? std::string("0")
            : std::isfinite(m.logDecrement) ? formatValue(m.logDecrement)
                                            : std::string("inf"))
        << "  " << whirlName(m.whirl) << "\n";
  }
  // The pads' own modes (tilting pads kept as dofs), apart: their eigenvalue and the share of
  // their energy in the pads' tilts.
  for (std::size_t i = 0; i < r.bearingModes.size(); ++i) {
    const RotorMode& m = r.bearingModes[i];
    out << "    pad mode " << i + 1 << "  eigenvalue " << formatValue(m.eigenvalue.real());
    if (m.eigenvalue.imag() != 0) out << " + " << formatValue(m.eigenvalue.imag()) << "i";
    out << " 1/s  damping " << formatValue(m.dampingRatio) << "  energy in the pads "
        << formatValue(m.bearingEnergy) << "\n";
  }
}

void printRotor(std::ostream& out, const AnalysisOutcome& a, const CampbellOutcome& r,
                const OutputUnits& units) {
  const CampbellResult& c = r.campbell;
  out << "campbell analysis '" << a.name << "' (" << c.lines.size() << " lines, " << c.speeds.size()
      << " speeds " << rpmText(c.speeds.front() * kRpm, units) << " to "
      << rpmText(c.speeds.back() * kRpm, units) << ")\n";
  printCoefficientsUsed(out, c.coefficients);
  if (r.criticalSpeeds.empty())
    out << "    no critical speed (" << formatValue(r.order) << "x) in this range\n";
  // Numbered as the check quantity `critical_speed N` reads them.
  for (std::size_t i = 0; i < r.criticalSpeeds.size(); ++i) {
    const CriticalSpeed& k = r.criticalSpeeds[i];
    out << "    critical speed " << i + 1 << ": " << rpmText(k.rpm, units) << " ("
        << hzText(k.frequencyHz, units) << ", line " << k.line + 1 << ", "
        << whirlName(k.whirl) << " whirl)\n";
  }
  for (const CriticalSpeed& k : r.furtherCriticalSpeeds)
    out << "    " << formatValue(k.order) << "x speed meets line " << k.line + 1 << " at "
        << rpmText(k.rpm, units) << " (" << hzText(k.frequencyHz, units) << ", "
        << whirlName(k.whirl) << " whirl)\n";
  // The least damped line: its smallest log decrement over the sweep.
  if (const auto least = leastDamped(c))
    out << "    smallest log decrement " << formatValue(least->logDecrement) << " (line "
        << least->line + 1 << " at " << rpmText(c.speeds[least->speed] * kRpm, units) << ")\n";
  if (r.onset)
    out << "    UNSTABLE above " << rpmText(r.onset->rpm, units) << " (onset of instability: "
        << hzText(r.onset->frequencyHz, units) << " " << whirlName(r.onset->whirl) << " whirl)\n";
  else
    out << "    stable over the sweep (no log decrement falls through zero)\n";
  // Each journal or tilting-pad bearing at the sweep's ends (its whole table in the CSV).
  for (const JournalBearingCurve& j : r.journals)
    for (std::size_t s : {std::size_t(0), j.speeds.size() - 1}) {
      const BearingCoefficients& k = j.coefficients[s];
      const OutputUnits::Shown stiffness = units.valueIn("N/m", {1, "N/m"});
      const OutputUnits::Shown damping = units.valueIn("N s/m", {1, "N s/m"});
      // A coefficient that should vanish (a symmetric bearing's cross-coupling) comes out of
      // the film's sums as round-off of the largest: judged against its own matrix's largest.
      const double stiffest =
          std::max({std::abs(k.kyy), std::abs(k.kzz), std::abs(k.kyz), std::abs(k.kzy)});
      const double dampest =
          std::max({std::abs(k.cyy), std::abs(k.czz), std::abs(k.cyz), std::abs(k.czy)});
      const auto in = [](double v, double largest, const OutputUnits::Shown& shown) {
        return formatValue(zeroAtOrBelow(v, kNegligibleShare * largest) * shown.factor);
      };
      const auto kIn = [&](double v) { return in(v, stiffest, stiffness); };
      const auto cIn = [&](double v) { return in(v, dampest, damping); };
      out << "    bearing " << j.name << " (" << j.type << ") at "
          << rpmText(j.speeds[s] * kRpm, units) << ": eccentricity "
          << formatValue(j.eccentricity[s]) << ", kxx " << kIn(k.kyy) << ", kyy " << kIn(k.kzz)
          << ", kxy " << kIn(k.kyz) << ", kyx " << kIn(k.kzy) << " " << stiffness.unit << ", cxx "
          << cIn(k.cyy) << ", cyy " << cIn(k.czz) << " " << damping.unit << "\n";
    }
}

void printRotor(std::ostream& out, const AnalysisOutcome& a, const UnbalanceOutcome& r,
                const OutputUnits& units) {
  const UnbalanceResult& u = r.unbalance;
  out << "unbalance analysis '" << a.name << "' (" << u.speeds.size() << " speeds)\n";
  for (std::size_t k = 0; k < r.responsePoints.size(); ++k) {
    std::size_t peak = 0;
    for (std::size_t s = 0; s < u.speeds.size(); ++s)
      if (u.orbits[k][s].major() > u.orbits[k][peak].major()) peak = s;
    out << "    " << r.responsePoints[k] << ": largest orbit "
        << valueText(u.orbits[k][peak].major(), "m", units) << " at " << rpmText(u.speeds[peak] * kRpm, units)
        << "\n";
  }
  if (!r.operating) return;
  out << "    API 684, operating range " << rpmText(r.operating->minimum * kRpm, units) << " to "
      << rpmText(r.operating->maximum * kRpm, units) << ":\n";
  for (std::size_t k = 0; k < r.peaks.size(); ++k)
    for (const ResponsePeak& p : r.peaks[k]) {
      out << "      " << r.responsePoints[k] << ": peak " << valueText(p.amplitude, "m", units) << " at "
          << rpmText(p.speed * kRpm, units) << ", ";
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
  if (r.stability) printOperatingStability(out, *r.stability, units);
  printApi684Verdict(out, r, units);
}

void printRotor(std::ostream& out, const AnalysisOutcome& a, const RigidBodyOutcome& r,
                const OutputUnits& units) {
  out << "rigid-body analysis '" << a.name << "': m = " << valueText(r.body.m, "kg", units)
      << ", centre of mass x = " << valueText(r.body.xG, "m", units)
      << ", J = " << valueText(r.body.J, "kg m^2", units)
      << " (mode amplitudes scaled to z^2 + rho^2 phi^2 = 1 m^2; bearing loads scale"
         " with the amplitude)\n";
  for (std::size_t i = 0; i < r.modes.size(); ++i) {
    const FormeShaftMode& m = r.modes[i];
    // The bearing forces of a unit modal amplitude: a force per length.
    out << "    two-dof mode " << i + 1 << " (the paper's " << paperModeName(int(i)) << ")  "
        << hzText(m.k / (2 * std::numbers::pi), units) << " (k = " << formatValue(m.k)
        << " rad/s)  " << modeShapeText(m, units) << "  F_" << r.points[0] << " = "
        << valueText(m.FA, "N/m", units) << ", F_" << r.points[1] << " = "
        << valueText(m.FB, "N/m", units) << " of modal amplitude\n";
  }
}

void printRotor(std::ostream& out, const AnalysisOutcome& a, const FrequencyResponseOutcome& r,
                const OutputUnits& units) {
  const FrequencyResponseResult& f = r.response;
  std::size_t peak = 0;
  for (std::size_t i = 0; i < f.receptance.size(); ++i)
    if (std::abs(f.receptance[i]) > std::abs(f.receptance[peak])) peak = i;
  out << "frequency-response analysis '" << a.name << "' at " << rpmText(f.speed * kRpm, units)
      << ": " << r.output << " / " << r.input << ", " << f.frequencies.size()
      << " frequencies\n";
  if (!f.receptance.empty())
    out << "    largest receptance " << formatValue(std::abs(f.receptance[peak])) << " at "
        << hzText(f.frequencies[peak] / (2 * std::numbers::pi), units) << "\n";
}

void printRotor(std::ostream& out, const AnalysisOutcome& a, const CriticalSpeedMapOutcome& r,
                const OutputUnits& units) {
  const CriticalSpeedMap& m = r.map;
  out << "critical-speed-map analysis '" << a.name << "' (" << m.stiffness.size()
      << " bearing stiffnesses " << formatValue(m.stiffness.front()) << " to "
      << valueText(m.stiffness.back(), "N", units) << "/m, gyroscopic moments neglected, "
      << formatValue(r.time) << " s)\n";
  const auto list = [&](const char* what, const std::vector<double>& speeds) {
    out << "    " << what;
    const OutputUnits::Shown speed = units.valueIn("rpm", {1, "rpm"});
    for (double s : speeds) out << " " << formatValue(s * kRpm * speed.factor);
    out << " " << speed.unit << "\n";
  };
  list("rigid bearings:", m.pinned);
  list("free-free rotor:", m.freeFree);
  for (const BearingStiffnessCurve& b : r.bearings)
    for (const auto& [what, crossings] :
         {std::pair{"kxx", &b.kxxCrossings}, std::pair{"kyy", &b.kyyCrossings}}) {
      out << "    bearing " << b.name << " " << what << " meets the map at";
      if (crossings->empty()) out << " no critical speed in range";
      for (const MapCrossing& c : *crossings)
        out << " " << rpmText(c.speed * kRpm, units) << " (critical speed " << c.line + 1
            << ")";
      out << "\n";
    }
}

void printRotor(std::ostream& out, const AnalysisOutcome& a, const BearingLoadsOutcome& r,
                const OutputUnits& units) {
  const GravityLoads& g = r.loads;
  out << "bearing-loads analysis '" << a.name << "' (" << (r.rigidBearings ? "pinned" : "elastic")
      << " bearings, weight " << valueText(g.weight.norm(), "N", units) << ")\n";
  for (std::size_t i = 0; i < g.bearings.size(); ++i) {
    const BearingForce& b = g.bearings[i];
    out << "    bearing " << r.bearingNames.at(i) << " at x = " << valueText(b.x, "m", units)
        << " carries " << valueText(std::hypot(b.fy, b.fz), "N", units) << " (fy "
        << valueText(b.fy, "N", units)
        << ", fz " << valueText(b.fz, "N", units) << " on the shaft)\n";
  }
  const int worst = g.largestSag();
  if (worst >= 0)
    out << "    largest sag " << valueText(std::hypot(g.uy[worst], g.uz[worst]), "m", units) << " at x = "
        << valueText(g.x[worst], "m", units) << "\n";
}

void printRotor(std::ostream& out, const AnalysisOutcome& a, const LevelOneOutcome& o,
                const OutputUnits& units) {
  const LevelOneResult& r = o.screening;
  out << "level1-stability analysis '" << a.name << "' at " << rpmText(r.speed * kRpm, units)
      << ", cross-coupling at " << o.station << " (" << formatValue(o.time) << " s)\n"
      << "    Qa " << valueText(r.anticipated, "N/m", units) << " from " << o.stages
      << " stage(s) (API 617); least log decrement " << formatValue(r.baseLogDecrement)
      << " without, " << formatValue(r.logDecrementAtQa) << " at Qa ("
      << hzText(r.frequencyHzAtQa, units) << (r.bearingModeAtQa ? ", a pad mode" : "") << ")\n";
  if (r.found)
    out << "    Q0 " << valueText(r.zeroDecrement, "N/m", units) << " (" << whirlName(r.whirlAtQ0)
        << " whirl at " << hzText(r.frequencyHzAtQ0, units)
        << (r.bearingModeAtQ0 ? ", a pad mode" : "") << "), Q0/Qa " << formatValue(r.ratio)
        << "\n";
  else
    out << "    Q0 not found: no cross-coupling up to 2^40 Qa destabilises the rotor\n";
  out << "    CSR " << formatValue(r.map.ratio) << " (MCOS "
      << rpmText(r.map.maximumContinuousSpeed * kRpm, units) << " / rigid-support critical "
      << rpmText(r.map.rigidCriticalSpeed * kRpm, units) << ") at average gas density "
      << formatValue(r.map.averageDensity) << " kg/m^3: region " << (r.map.regionB ? "B" : "A")
      << " of API 617's map (boundary CSR " << formatValue(r.map.boundary) << ")\n";
  out << "    API 684 Level I: " << levelOneVerdict(r) << "\n";
}

void printRotor(std::ostream& out, const AnalysisOutcome& a, const RunUpOutcome& o,
                const OutputUnits& units) {
  const RunUpResult& r = o.runUp;
  const double from = r.speed.empty() ? 0 : r.speed.front(), to = r.speed.empty() ? 0 : r.speed.back();
  out << "run-up analysis '" << a.name << "': " << (to >= from ? "run-up" : "coast-down")
      << " from " << rpmText(from * kRpm, units) << " to " << rpmText(to * kRpm, units)
      << " in " << formatValue(r.times.empty() ? 0 : r.times.back()) << " s, " << r.steps
      << " steps of " << formatValue(r.timeStep) << " s ("
      << (o.alpha == 0 ? std::string("newmark") : "hht alpha " + formatValue(o.alpha)) << ", "
      << formatValue(r.time.total) << " s)\n";
  if (r.driven && !r.speed.empty())
    out << "    speed driven by a torque on " << formatValue(o.inertia) << " kg m^2"
        << " of polar inertia: " << rpmText(r.speed.back() * kRpm, units) << " at the end (torque "
        << valueText(r.driveTorque.back(), "N m", units) << ")\n";
  for (std::size_t k = 0; k < o.responsePoints.size(); ++k) {
    const RunUpHistory& h = r.histories[k];
    out << "    " << o.responsePoints[k] << ": ";
    if (h.revolutions.amplitude.empty()) {
      out << "no revolution completed\n";
      continue;
    }
    out << "peak amplitude " << valueText(h.peakAmplitude, "m", units) << " at "
        << rpmText(h.speedAtPeak * kRpm, units) << " (t = " << formatValue(h.timeAtPeak)
        << " s)\n";
  }
  for (const JournalTrack& j : r.journals) {
    out << "    journal '" << j.name << "' on its film: eccentricity "
        << formatValue(j.startEccentricity) << " at the start, at most "
        << formatValue(j.largestEccentricity) << " (c = " << valueText(j.clearance, "m", units)
        << ")\n";
    // A tilting-pad film's pads, each tilt's range over the samples.
    if (!j.ownNames.empty()) out << "      pads' tilts over the run:";
    for (std::size_t k = 0; k < j.ownNames.size(); ++k)
      if (const auto range = j.ownRange(k))
        out << (k ? ", " : " ") << j.ownNames[k] << " " << valueText(range->first, "rad", units)
            << " to " << valueText(range->second, "rad", units);
    if (!j.ownNames.empty()) out << "\n";
  }
  if (!r.filmTorque.empty())
    out << "    the films' drag on the spin: " << valueText(r.filmTorque.front(), "N m", units)
        << " at the start, " << valueText(r.filmTorque.back(), "N m", units) << " at the end\n";
  for (const RubTrack& t : r.rubs) {
    out << "    rub '" << t.name << "' (c = " << valueText(t.clearance, "m", units) << "): ";
    if (t.firstContact < 0) {
      out << "no contact\n";
      continue;
    }
    out << "in contact " << formatValue(t.contactTime) << " s from t = "
        << formatValue(t.firstContact) << " s, peak normal force "
        << valueText(t.peakNormal, "N", units) << ", peak rub torque "
        << valueText(t.peakTorque, "N m", units) << ", friction dissipated "
        << valueText(t.frictionWork, "J", units) << "\n";
  }
  if (!r.journals.empty() || !r.rubs.empty())
    out << "    Newton: " << r.newtonIterations << " iterations over " << r.steps
        << " steps, at most " << r.mostNewtonIterations << " in one\n";
  const RunUpEnergy& e = r.energy;
  if (!e.kinetic.empty()) {
    const std::size_t last = e.kinetic.size() - 1;
    out << "    energy at the end: kinetic " << valueText(e.kinetic[last], "J", units)
        << ", strain " << valueText(e.strain[last], "J", units) << ", dissipated "
        << valueText(e.dissipated[last], "J", units)
        << (r.journals.empty() ? std::string()
                               : ", against the films " + valueText(e.film[last], "J", units))
        << (r.rubs.empty() ? std::string()
                           : ", against the rubs " + valueText(e.rub[last], "J", units))
        << ", work of unbalance and gravity "
        << valueText(e.work[last], "J", units) << " (balance "
        << valueText(e.balance(last), "J", units) << ")\n";
  }
}

}  // namespace beamrotor::cli

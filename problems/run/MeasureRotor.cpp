// Measuring the rotor analyses' check quantities (problems/deck/rotor/RotorQuantity.hpp).
#include "problems/run/MeasureRotor.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>

namespace beamrotor {

namespace {

constexpr double kRpm = 30 / std::numbers::pi;  // rad/s -> rpm

/// A speed in a sweep equal to `rpm` up to the round-off of converting it (the runner adds
/// every checked speed to the sweep, so it is there).
int speedIndex(const std::vector<double>& speeds, double rpm) {
  for (int s = 0; s < int(speeds.size()); ++s)
    if (std::abs(speeds[s] * kRpm - rpm) <= 1e-12 * std::max(1.0, std::abs(rpm))) return s;
  return -1;
}

double rigidBodyProperty(const RigidBodyOutcome& r, const std::string& p) {
  if (p.rfind("paper_", 0) == 0)  // paper_f1 .. paper_n2: the paper's k1 is our mode 2
    return rigidBodyProperty(
        r, p.substr(6, 1) + std::to_string(ascendingIndexOfPaperMode(p.back() - '0') + 1));
  if (p == "mass") return r.body.m;
  if (p == "com_x") return r.body.xG;
  if (p == "J_com") return r.body.J;
  if (p == "Jp") return r.body.Jp;
  const int i = p.back() - '1';  // f1 f2 n1 n2 FA1 FB1 FA2 FB2
  if (p[0] == 'f') return r.modes[i].k / (2 * std::numbers::pi);
  if (p[0] == 'F') return p[1] == 'A' ? r.modes[i].FA : r.modes[i].FB;
  if (!std::isfinite(r.modes[i].n))
    throw std::invalid_argument(p + " is infinite: mode " + std::to_string(i + 1) +
                                " is a pure bounce (C1 l1 = C2 l2, the paper's n = 0/0)");
  return r.modes[i].n;
}

}  // namespace

double measureRotor(const Quantity& q, const AnalysisOutcome& outcome) {
  const std::string name = "analysis '" + outcome.name + "'";
  switch (q.kind) {
    case Quantity::Kind::frequency:
    case Quantity::Kind::logDecrement: {
      const auto* r = resultOf<RotorModesResult>(outcome);
      if (!r) throw std::invalid_argument(name + " is not a rotor analysis");
      if (q.mode > int(r->modes.size()))
        throw std::invalid_argument(name + " found only " + std::to_string(r->modes.size()) +
                                    " modes");
      const RotorMode& m = r->modes[q.mode - 1];
      if (q.kind == Quantity::Kind::frequency) return m.dampedFrequencyHz;
      if (!std::isfinite(m.logDecrement))
        throw std::invalid_argument("mode " + std::to_string(q.mode) +
                                    " has a real eigenvalue (overdamped or unstable without "
                                    "oscillation): its log decrement is infinite");
      return m.logDecrement;
    }
    case Quantity::Kind::padMode: {
      const auto* r = resultOf<RotorModesResult>(outcome);
      if (!r) throw std::invalid_argument(name + " is not a rotor analysis");
      if (q.mode > int(r->bearingModes.size()))
        throw std::invalid_argument(name + " found " + std::to_string(r->bearingModes.size()) +
                                    " pad modes, not " + std::to_string(q.mode));
      const RotorMode& m = r->bearingModes[q.mode - 1];
      if (q.property == "frequency") return m.dampedFrequencyHz;
      if (q.property == "decay_rate") return -m.eigenvalue.real();
      if (q.property == "damping_ratio") return m.dampingRatio;
      if (q.property == "bearing_energy") return m.bearingEnergy;
      if (!std::isfinite(m.logDecrement))
        throw std::invalid_argument("pad mode " + std::to_string(q.mode) +
                                    " has a real eigenvalue (a massless pad's relaxation): its "
                                    "log decrement is infinite; read its decay_rate");
      return m.logDecrement;
    }
    case Quantity::Kind::criticalSpeed: {
      const auto* r = resultOf<CampbellOutcome>(outcome);
      if (!r) throw std::invalid_argument(name + " is not a campbell analysis");
      if (q.mode > int(r->criticalSpeeds.size()))
        throw std::invalid_argument(name + " found " + std::to_string(r->criticalSpeeds.size()) +
                                    " critical speeds in its speed range, not " +
                                    std::to_string(q.mode));
      return r->criticalSpeeds[q.mode - 1].rpm;
    }
    case Quantity::Kind::instabilityOnset: {
      const auto* r = resultOf<CampbellOutcome>(outcome);
      if (!r) throw std::invalid_argument(name + " is not a campbell analysis");
      if (!r->onset)
        throw std::invalid_argument(name + " finds no onset of instability in its speed range");
      return r->onset->rpm;
    }
    case Quantity::Kind::unbalanceAmplitude: {
      const auto* r = resultOf<UnbalanceOutcome>(outcome);
      if (!r) throw std::invalid_argument(name + " is not an unbalance analysis");
      const int s = speedIndex(r->unbalance.speeds, q.rpm);
      for (std::size_t k = 0; k < r->responsePoints.size(); ++k)
        if (r->responsePoints[k] == q.target && s >= 0) return r->unbalance.orbits[k][s].major();
      throw std::invalid_argument(name + " has no response of '" + q.target + "' at " +
                                  std::to_string(q.rpm) + " rpm");
    }
    case Quantity::Kind::rigidBody: {
      const auto* r = resultOf<RigidBodyOutcome>(outcome);
      if (!r) throw std::invalid_argument(name + " is not a rigid-body analysis");
      return rigidBodyProperty(*r, q.property);
    }
    case Quantity::Kind::levelOne: {
      const auto* r = resultOf<LevelOneOutcome>(outcome);
      if (!r) throw std::invalid_argument(name + " is not a level1-stability analysis");
      const LevelOneResult& s = r->screening;
      if (q.property == "qa") return s.anticipated;
      if (q.property == "log_decrement_at_qa") return s.logDecrementAtQa;
      if (q.property == "critical_speed_ratio") return s.map.ratio;
      if (q.property == "rigid_critical_speed") return s.map.rigidCriticalSpeed * kRpm;
      if (!s.found)
        throw std::invalid_argument(name + " finds no Q0: no cross-coupling up to 2^40 Qa "
                                    "destabilises the rotor");
      return q.property == "q0" ? s.zeroDecrement : s.ratio;
    }
    case Quantity::Kind::runUp: {
      const auto* r = resultOf<RunUpOutcome>(outcome);
      if (!r) throw std::invalid_argument(name + " is not a run-up analysis");
      if (q.property == "end_speed")
        return r->runUp.speed.empty() ? 0.0 : r->runUp.speed.back() * kRpm;
      if (q.property == "eccentricity") {
        for (const JournalTrack& j : r->runUp.journals)
          if (j.name == q.target) return j.largestEccentricity;
        throw std::invalid_argument(name + " has no nonlinear journal bearing '" + q.target + "'");
      }
      if (q.property == "film_torque") {
        if (r->runUp.filmTorque.empty())
          throw std::invalid_argument(name + " runs no journal film (bearings: nonlinear)");
        return r->runUp.filmTorque.back();
      }
      if (q.property.starts_with("rub_")) {
        for (const RubTrack& t : r->runUp.rubs)
          if (t.name == q.target)
            return q.property == "rub_force"    ? t.peakNormal
                   : q.property == "rub_torque" ? t.peakTorque
                                                : t.contactTime;
        throw std::invalid_argument(name + " has no rub station '" + q.target + "'");
      }
      for (std::size_t k = 0; k < r->responsePoints.size(); ++k) {
        if (r->responsePoints[k] != q.target) continue;
        const RunUpHistory& h = r->runUp.histories[k];
        if (h.revolutions.amplitude.empty())
          throw std::invalid_argument(name + " completes no revolution: no amplitude of '" +
                                      q.target + "'");
        return q.property == "peak" ? h.peakAmplitude : h.speedAtPeak * kRpm;
      }
      throw std::invalid_argument(name + " has no response of '" + q.target + "'");
    }
    default:
      throw std::invalid_argument("'" + q.text + "' is not a result of " + name);
  }
}

}  // namespace beamrotor

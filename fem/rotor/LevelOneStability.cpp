#include "fem/rotor/LevelOneStability.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>
#include <string>

#include "fem/rotor/RotorStability.hpp"
#include "fem/rotor/RotorSystem.hpp"

namespace beamrotor {

namespace {

/// Doublings of Q_hi from Qa before giving up on a bracket: 2^40 Qa is far beyond any
/// cross-coupling a machine meets.
constexpr int kDoublings = 40;

/// The least damped of a set of modes: its neutral log decrement, frequency and whirl, and
/// whether it is a bearing's own mode (a pad's, RotorModesResult::bearingModes).
struct Worst {
  double growth = -std::numeric_limits<double>::infinity();
  double logDecrement = std::numeric_limits<double>::infinity();
  double frequencyHz = 0;
  Whirl whirl = Whirl::planar;
  bool bearingMode = false;
};

/// The least damped of the rotor's modes and the bearings' own (pads kept as dofs): a pad's
/// mode is the least damped only when its log decrement is the least of all (a massless pad's
/// relaxation, a real eigenvalue that decays, never is).
Worst worstOf(const RotorModesResult& result) {
  Worst w;
  for (const auto* modes : {&result.modes, &result.bearingModes})
    for (const RotorMode& m : *modes) {
      const double delta = neutralLogDecrement(m);
      if (std::isnan(delta) || delta >= w.logDecrement) continue;
      w = {growthRate(m), delta, m.dampedFrequencyHz, m.whirl, modes == &result.bearingModes};
    }
  return w;
}

void requirePositive(double value, const std::string& what) {
  if (!(value > 0) || !std::isfinite(value))
    throw std::invalid_argument("API 617: " + what + " must be > 0 (got " +
                                std::to_string(value) + ")");
}

}  // namespace

double anticipatedCrossCoupling(const std::vector<CompressorStage>& stages, double speed) {
  requirePositive(speed, "the speed");
  double sum = 0;
  for (const CompressorStage& s : stages) {
    if (!(s.power >= 0)) throw std::invalid_argument("API 617 Qa: a stage's power must be >= 0");
    requirePositive(s.diameter, "a stage's impeller diameter");
    requirePositive(s.tipWidth, "a stage's tip width");
    requirePositive(s.dischargeDensity, "a stage's discharge density");
    requirePositive(s.suctionDensity, "a stage's suction density");
    const double torque = s.power / speed;  // N m: C P_r / N in API's units
    sum += kCentrifugalStageFactor * torque / (s.diameter * s.tipWidth) *
           (s.dischargeDensity / s.suctionDensity);
  }
  return sum;
}

double criticalSpeedRatioBoundary(double averageDensity) {
  // API 617 7th ed. fig. 2-7 (ROSS's digitisation): flat at 2.5, then falling linearly to 2.0
  // at 60 kg/m^3; denser gas lies in region B at any ratio.
  constexpr double kFlatUpTo = 16.53, kDenseFrom = 60;
  if (averageDensity <= kFlatUpTo) return 2.5;
  if (averageDensity <= kDenseFrom) return 2.69 - 0.0115 * averageDensity;
  return 0;
}

CriticalSpeedRatioPoint criticalSpeedRatioPoint(double maximumContinuousSpeed,
                                                double rigidCriticalSpeed,
                                                double averageDensity) {
  requirePositive(maximumContinuousSpeed, "the maximum continuous speed");
  requirePositive(rigidCriticalSpeed, "the critical speed on rigid supports");
  if (!(averageDensity >= 0) || !std::isfinite(averageDensity))
    throw std::invalid_argument("API 617 CSR map: the average gas density must be >= 0");
  CriticalSpeedRatioPoint p;
  p.maximumContinuousSpeed = maximumContinuousSpeed;
  p.rigidCriticalSpeed = rigidCriticalSpeed;
  p.averageDensity = averageDensity;
  p.ratio = maximumContinuousSpeed / rigidCriticalSpeed;
  p.boundary = criticalSpeedRatioBoundary(averageDensity);
  p.regionB = p.ratio > p.boundary;
  return p;
}

double averageGasDensity(const std::vector<CompressorStage>& stages) {
  if (stages.empty()) throw std::invalid_argument("API 617 CSR map: no stages");
  return 0.5 * (stages.front().suctionDensity + stages.back().dischargeDensity);
}

LevelOneResult levelOneStability(const Model& model, const RotorOptions& options, int node,
                                 double speed, double anticipated,
                                 const CriticalSpeedRatioPoint& map, double tolerance,
                                 int samples) {
  if (!(anticipated > 0) || !std::isfinite(anticipated))
    throw std::invalid_argument("API 684 Level I: Qa must be > 0");
  RotorSystem system(model, options.damping);
  QuadraticEigenSolver solver;
  LevelOneResult out;
  out.speed = speed;
  out.node = node;
  out.anticipated = anticipated;
  const auto at = [&](double q) {
    system.setCrossCoupling(node, q);
    return worstOf(solveRotorModes(system, speed, options, solver, false));
  };

  // 1. Without added cross-coupling, and with Qa.
  const Worst base = at(0);
  out.baseLogDecrement = base.logDecrement;
  const Worst withQa = at(anticipated);
  out.logDecrementAtQa = withQa.logDecrement;
  out.frequencyHzAtQa = withQa.frequencyHz;
  out.bearingModeAtQa = withQa.bearingMode;

  // 2. Q0: a bracket [lo, hi] with the growth rate <= 0 at lo and > 0 at hi, then its root.
  if (base.growth >= 0) {  // no margin at all: Q0 = 0
    out.found = true;
    out.frequencyHzAtQ0 = base.frequencyHz;
    out.whirlAtQ0 = base.whirl;
    out.bearingModeAtQ0 = base.bearingMode;
  } else {
    double lo = 0, hi = anticipated;
    Worst fLo = base, fHi = withQa;
    out.evaluations = 2;
    for (int i = 0; i < kDoublings && !(fHi.growth > 0); ++i) {
      lo = hi;
      fLo = fHi;
      hi *= 2;
      fHi = at(hi);
      ++out.evaluations;
    }
    if (fHi.growth > 0) {
      Worst last;
      const SpeedRoot root = speedRoot(
          [&](double q) {
            last = at(q);
            return last.growth;
          },
          lo, fLo.growth, hi, fHi.growth, tolerance);
      if (root.evaluations == 0) last = at(root.speed);
      out.evaluations += std::max(root.evaluations, 1);
      out.found = true;
      out.zeroDecrement = root.speed;
      out.frequencyHzAtQ0 = last.frequencyHz;
      out.whirlAtQ0 = last.whirl;
      out.bearingModeAtQ0 = last.bearingMode;
    }
  }
  out.ratio = out.found ? out.zeroDecrement / anticipated
                        : std::numeric_limits<double>::infinity();
  out.mapDecides = out.ratio >= kLevelOneMinimumRatio && out.ratio < kLevelOneRegionRatio;
  out.map = map;
  out.pass = out.logDecrementAtQa >= kLevelOneLogDecrement &&
             out.ratio >= kLevelOneMinimumRatio && !(out.mapDecides && map.regionB);

  // 3. The curve for the chart.
  const double top = 1.5 * std::max(out.found ? out.zeroDecrement : 0.0, anticipated);
  for (int i = 0; i <= samples; ++i) {
    const double q = top * i / std::max(samples, 1);
    out.curve.push_back({q, at(q).logDecrement});
  }
  return out;
}

}  // namespace beamrotor

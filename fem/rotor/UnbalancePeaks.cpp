// API 684 reading with modal damping for overlapping peaks (see UnbalancePeaks.hpp).
#include "fem/rotor/UnbalancePeaks.hpp"

#include <cmath>
#include <complex>

#include "fem/rotor/RotorModes.hpp"
#include "fem/solvers/Errors.hpp"

namespace beamrotor {

namespace {

/// Modes asked for around the synchronous frequency: the one met and its neighbours (a
/// double mode's two planes, the other whirl sense).
constexpr int kModesAroundPeak = 4;

}  // namespace

double synchronousModeDamping(const Model& model, const ProportionalDamping& damping,
                              double speed) {
  RotorOptions options;
  options.modes = kModesAroundPeak;
  options.shift = std::complex<double>(0, speed);  // eigenvalues nearest i Omega
  options.damping = damping;
  const RotorModesResult r = solveRotorModes(model, speed, options);
  const RotorMode* met = nullptr;
  for (const RotorMode& m : r.modes)
    if (!met || std::abs(m.dampedFrequency - speed) < std::abs(met->dampedFrequency - speed))
      met = &m;
  return met ? met->dampingRatio : 0;
}

std::vector<ResponsePeak> unbalancePeaks(const Model& model, const ProportionalDamping& damping,
                                         const std::vector<double>& speeds,
                                         const std::vector<double>& amplitudes,
                                         const OperatingRange& operating) {
  std::vector<ResponsePeak> peaks = readResponsePeaks(speeds, amplitudes, operating);
  for (ResponsePeak& p : peaks) {
    if (p.method != AmplificationMethod::none) continue;
    double zeta = 0;
    try {
      zeta = synchronousModeDamping(model, damping, p.speed);
    } catch (const SolveError&) {
      continue;  // the shift hit an undamped eigenvalue exactly: no finite factor anyway
    }
    if (zeta > 0) useModalDamping(p, zeta, operating);
  }
  return peaks;
}

}  // namespace beamrotor

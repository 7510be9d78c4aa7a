// The API 684 reading of a rotor's unbalance response (fem/rotor/Api684.hpp) with the model at
// hand: the half-power method where the peaks stand apart, the damped modes' damping where
// two peaks overlap.
#pragma once

#include <vector>

#include "fem/model/Model.hpp"
#include "fem/rotor/Api684.hpp"
#include "fem/rotor/RotorSystem.hpp"

namespace beamrotor {

/// The peaks of one response point's orbit semi-major axes `amplitudes` at the ascending
/// `speeds` (rad/s), read by readResponsePeaks. Each overlapping peak (and each other peak
/// without half-power points) then gets AF = 1 / (2 zeta) by useModalDamping, zeta the damping
/// ratio of the model's damped mode at the peak's speed whose damped frequency lies nearest
/// that speed (the mode the synchronous excitation meets there). A peak whose mode is
/// undamped, unstable or cannot be computed keeps method none (AF unknown, fails).
std::vector<ResponsePeak> unbalancePeaks(const Model& model, const ProportionalDamping& damping,
                                         const std::vector<double>& speeds,
                                         const std::vector<double>& amplitudes,
                                         const OperatingRange& operating);

/// The damping ratio of the damped mode at spin speed `speed` (rad/s) whose damped frequency
/// lies nearest `speed`; 0 when no mode is found.
double synchronousModeDamping(const Model& model, const ProportionalDamping& damping,
                              double speed);

}  // namespace beamrotor

// A base-motion sweep's response on the mesh for ParaView, at the frequency of its largest
// base force: <stem>_base_motion_peak.vtu.
#pragma once

#include <cstddef>
#include <filesystem>
#include <string>

#include "fem/modal/BaseMotion.hpp"

namespace beamrotor {

/// The file's name for an analysis' stem.
std::string baseMotionVtu(const std::string& stem);

/// The sweep's point of the largest |base force| (the first when several tie).
std::size_t peakPoint(const BaseMotionResult& r);

/// Writes <stem>_base_motion_peak.vtu at peakPoint(r): the nodes and line elements with point
/// data (amplitudes, SI units named in each array) `relative amplitude [m]` (|ux| |uy| |uz|
/// relative to the ground), `absolute amplitude [m]` (the ground's motion added along its
/// direction), `rotation amplitude [rad]`, `transmissibility [1]` (|absolute acceleration| /
/// |a_g| along the direction) and `phase [deg]` (the absolute motion's phase against the
/// ground acceleration's, along the direction); field data `frequency [Hz]` and
/// `base force [N]` (its amplitude).
void writeBaseMotionVtu(const std::filesystem::path& dir, const Model& model,
                        const BaseMotionResult& r, const std::string& stem);

}  // namespace beamrotor

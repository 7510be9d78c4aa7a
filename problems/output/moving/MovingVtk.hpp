// A moving load's envelopes on the mesh for ParaView: <stem>_envelope.vtu.
#pragma once

#include <filesystem>
#include <string>

#include "fem/model/Model.hpp"
#include "problems/run/MovingLoadOutcome.hpp"

namespace beamrotor {

/// The file's name for an analysis' stem.
std::string movingVtu(const std::string& stem);

/// Writes <stem>_envelope.vtu: the model's nodes and line elements with (SI units, named in
/// each array's name) point data `displacement_max [m]`, `displacement_min [m]`,
/// `rotation_max [rad]`, `rotation_min [rad]` (each component's own extreme over the train's
/// positions), cell data `N_max [N]`, `N_min [N]`, ... `Mz_max [N m]`, `Mz_min [N m]` (the
/// extremes over both ends of the element, element frame), and for each quantity the
/// displaced shape where it is largest and smallest, point data `displacement at max of
/// QUANTITY [m]` and `rotation at max of QUANTITY [rad]` (and `min`), with the first wheel's
/// position in the field data `first wheel at max of QUANTITY [m]`. Everything includes the
/// deck's own loads when the analysis does.
void writeMovingVtu(const std::filesystem::path& dir, const Model& model,
                    const MovingLoadOutcome& m, const std::string& stem);

}  // namespace beamrotor

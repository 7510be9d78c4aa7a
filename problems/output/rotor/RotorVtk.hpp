// VTK files of damped rotor modes: the complex shape on the mesh, and the orbits it traces.
#pragma once

#include <filesystem>

#include "fem/model/Model.hpp"
#include "fem/rotor/RotorResults.hpp"

namespace beamrotor {

/// One rotor mode on the mesh (lineGrid): point data `shape_real`, `shape_imag` (ux uy uz,
/// largest translation 1) and `rotation_real`, `rotation_imag` (rx ry rz, same scale), so
/// that the motion is Re((real + i imag) e^{i omega t}); `orbit_semi_major` and
/// `whirl_ratio` per node (+1 circular forward, -1 backward, 0 a line). Field data `mode`,
/// `frequency_hz` (damped), `natural_frequency_hz`, `damping_ratio`, `whirl` (+1, -1, 0).
void writeRotorModeVtu(const std::filesystem::path& file, const Model& model, const RotorMode& mode,
                       int number);

/// The orbits of the same mode: per node a closed ring of 48 VTK_LINE cells (cells 48 n to
/// 48 n + 47) through x_node + s Re(shape e^{i theta}), theta over one period, with s = 0.1 of
/// the model's extent (the shape has largest translation 1); cell data `node` and
/// `orbit_semi_major`.
void writeOrbitVtu(const std::filesystem::path& file, const Model& model, const RotorMode& mode);

}  // namespace beamrotor

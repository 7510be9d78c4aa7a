// Campbell diagram: damped modes over a list of spin speeds, each mode followed from speed to
// speed by eigenvector correlation (MAC), so lines that cross (forward and backward whirl of
// neighbouring modes) keep their identity; critical speeds where a line meets order x Omega.
#pragma once

#include <vector>

#include "fem/rotor/RotorModes.hpp"

namespace beamrotor {

/// Modal assurance criterion |a^H b|^2 / (|a|^2 |b|^2) of two complex vectors: 1 for parallel
/// vectors whatever their complex scale, 0 for orthogonal ones.
double mac(const Eigen::VectorXcd& a, const Eigen::VectorXcd& b);

/// options.modes lines over `speeds` (rad/s, in sweep order). Each speed computes a few more
/// modes than asked, so a tracked mode that drops down the order is still found. One
/// assembly, one symbolic factorisation for the whole sweep.
CampbellResult solveCampbell(const Model& model, const std::vector<double>& speeds,
                             const RotorOptions& options = {});

/// Speeds where line l's damped frequency (rad/s) equals order * Omega, linearly
/// interpolated between the bracketing speeds of the sweep; ascending.
std::vector<CriticalSpeed> criticalSpeeds(const CampbellResult& campbell, double order = 1);

}  // namespace beamrotor

// Campbell diagram: damped modes over a list of spin speeds, each mode followed from speed to
// speed by eigenvector correlation (MAC), so lines that cross (forward and backward whirl of
// neighbouring modes) keep their identity; critical speeds where a line meets order x Omega.
#pragma once

#include <complex>
#include <vector>

#include "fem/rotor/RotorModes.hpp"

namespace beamrotor {

/// Modal assurance criterion |a^H b|^2 / (|a|^2 |b|^2) of two complex vectors: 1 for parallel
/// vectors whatever their complex scale, 0 for orthogonal ones.
double mac(const Eigen::VectorXcd& a, const Eigen::VectorXcd& b);
/// mac(a_k, b_l) of every column k of a and l of b.
Eigen::MatrixXd macTable(const Eigen::MatrixXcd& a, const Eigen::MatrixXcd& b);

/// How many modes a Campbell sweep computes per speed after the first, given the first
/// speed's `modes` (nearest `shift` first, `lines` of them followed plus a margin): the count
/// c, between lines + max(2, lines / 4) and modes.size(), after which the distance to the
/// shift grows by the largest factor. ARPACK converges at the rate of that factor: a count
/// that ends inside a cluster (|lambda_c+1 - shift| ~ |lambda_c - shift|) costs restarts, one
/// at a gap converges in one Krylov basis. modes.size() when no count is smaller.
int candidatesAtGap(const std::vector<RotorMode>& modes, int lines, std::complex<double> shift);

/// options.modes lines over `speeds` (rad/s, in sweep order). Each speed computes a few more
/// modes than asked (candidatesAtGap), so a tracked mode that drops down the order is still
/// found. One assembly, one symbolic factorisation for the whole sweep.
CampbellResult solveCampbell(const Model& model, const std::vector<double>& speeds,
                             const RotorOptions& options = {});

/// Speeds where line l's damped frequency (rad/s) equals order * Omega, linearly
/// interpolated between the bracketing speeds of the sweep; ascending.
std::vector<CriticalSpeed> criticalSpeeds(const CampbellResult& campbell, double order = 1);

}  // namespace beamrotor

// Campbell diagram: damped modes over a list of spin speeds, each mode followed from speed to
// speed by eigenvector correlation (MAC), so lines that cross (forward and backward whirl of
// neighbouring modes) keep their identity; critical speeds where a line meets order x Omega.
#pragma once

#include <complex>
#include <utility>
#include <vector>

#include "fem/rotor/RotorModes.hpp"

namespace beamrotor {

/// Modal assurance criterion |a^H b|^2 / (|a|^2 |b|^2) of two complex vectors: 1 for parallel
/// vectors whatever their complex scale, 0 for orthogonal ones.
double mac(const Eigen::VectorXcd& a, const Eigen::VectorXcd& b);
/// mac(a_k, b_l) of every column k of a and l of b.
Eigen::MatrixXd macTable(const Eigen::MatrixXcd& a, const Eigen::MatrixXcd& b);

/// Assigns each column of `lines` a column of `candidates` by descending MAC (greedy: the best
/// remaining pair first): the candidate of each line (-1 when the candidates run out) and its
/// MAC.
std::vector<std::pair<int, double>> matchByMac(const Eigen::MatrixXcd& lines,
                                               const Eigen::MatrixXcd& candidates);

/// How many modes a Campbell sweep computes at its first speed for `lines` lines: half as
/// many again (at least 2 more), so that a line dropping down the order is still found.
int firstCandidates(int lines);

/// How many modes a Campbell sweep computes per speed after the first, given the first
/// speed's `modes` (nearest `shift` first, `lines` of them followed plus a margin): the count
/// c, between lines + max(2, lines / 4) and modes.size(), after which the distance to the
/// shift grows by the largest factor. ARPACK converges at the rate of that factor: a count
/// that ends inside a cluster (|lambda_c+1 - shift| ~ |lambda_c - shift|) costs restarts, one
/// at a gap converges in one Krylov basis. modes.size() when no count is smaller.
int candidatesAtGap(const std::vector<RotorMode>& modes, int lines, std::complex<double> shift);

/// options.modes lines over `speeds` (rad/s, in sweep order). Each speed computes a few more
/// modes than asked (candidatesAtGap), so a tracked mode that drops down the order is still
/// found. One assembly, one symbolic factorisation for the whole sweep. With bearings' own
/// dofs (pad tilts) the candidates are every rotor mode of a speed's eigen-solution
/// (RotorOptions::everyRotorMode): a pad mode counted with the rotor's takes no candidate's
/// place.
///
/// A line whose shape correlates less than 0.5 with its last (MAC; but not where either is a
/// repeated eigenvalue, whose basis is arbitrary), or whose eigenvalue leaves the straight
/// continuation of its last two speeds by more than a quarter of its size, has likely changed
/// mode (its own left the candidates, or the step is too coarse for the
/// shapes to tell modes apart: modes dominated by one disk's orbit correlate near 1 whatever
/// else they do, so the MAC alone does not tell). That interval is swept again at
/// kLocalSteps speeds with twice the candidates, the lines followed through them; where that
/// finds the line's own mode again it is kept (and the wider candidates from there on), else
/// the jump is reported in `jumps`. A growing mode among the candidates that no line follows
/// is reported in `untracked`.
CampbellResult solveCampbell(const Model& model, const std::vector<double>& speeds,
                             const RotorOptions& options = {});

/// Where a line's damped frequency minus order x speed changes sign: between the sweep's
/// speeds `interval` and `interval` + 1, at the fraction t of that step by linear
/// interpolation. A zero at a sweep speed belongs to the interval it starts (the last speed's
/// to the last interval); a zero at the first speed is a zero frequency at rest, not a
/// resonance.
struct CrossingBracket {
  int line = -1;
  std::size_t interval = 0;
  double t = 0;
};
std::vector<CrossingBracket> crossingBrackets(const CampbellResult& campbell, double order);

/// Critical speeds in the order they are numbered: ascending, and crossings at one speed (the
/// two whirls of an isotropic rotor's double mode) forward whirl first, the one an unbalance
/// drives, then planar, then backward.
void sortCriticalSpeeds(std::vector<CriticalSpeed>& speeds);

/// Speeds where line l's damped frequency (rad/s) equals order * Omega, linearly
/// interpolated between the bracketing speeds of the sweep (what a refinement on the speed
/// starts from, CriticalSpeedRefinement.hpp); sorted by sortCriticalSpeeds.
std::vector<CriticalSpeed> criticalSpeeds(const CampbellResult& campbell, double order = 1);

}  // namespace beamrotor

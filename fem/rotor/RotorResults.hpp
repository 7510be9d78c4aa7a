// Results of the rotor analyses as plain values (see fem/model/Results.hpp for the static and modal
// ones). Spin about global +x; frequencies in rad/s and Hz, speeds in rad/s.
#pragma once

#include <complex>
#include <optional>
#include <string_view>
#include <vector>

#include "fem/model/Results.hpp"

namespace beamrotor {

/// Complex amplitudes per node and dof kind (rows: nodes; columns ux uy uz rx ry rz, global
/// frame); the motion is Re(value * e^{lambda t}). Dofs the model does not carry are zero.
using ComplexNodalField =
    Eigen::Matrix<std::complex<double>, Eigen::Dynamic, kDofKinds, Eigen::RowMajor>;

/// Sense of a mode's orbit relative to the spin (about +x: from +y towards +z).
enum class Whirl {
  forward,   ///< with the spin
  backward,  ///< against the spin
  planar,    ///< a straight line (no sense): non-rotating, or real eigenvalue
};
std::string_view whirlName(Whirl w);

/// The orbit Re((uy, uz) e^{i w t}) of one node: split into a forward circle of radius
/// |uy + i uz| / 2 and a backward one of radius |uy - i uz| / 2.
struct Orbit {
  std::complex<double> uy, uz;  ///< complex amplitudes (m)

  double forwardRadius() const { return std::abs(uy + std::complex<double>(0, 1) * uz) / 2; }
  double backwardRadius() const { return std::abs(uy - std::complex<double>(0, 1) * uz) / 2; }
  /// Semi-axes of the orbit ellipse (m).
  double major() const { return forwardRadius() + backwardRadius(); }
  double minor() const { return std::abs(forwardRadius() - backwardRadius()); }
  /// (forward - backward) / (forward + backward): +1 circular forward, -1 circular backward,
  /// 0 a straight line; 0 for a node at rest.
  double whirlRatio() const;
};

/// One damped mode of M q'' + (C + Omega G) q' + K q = 0 at one speed: q = Re(shape e^{lambda t}).
struct RotorMode {
  std::complex<double> eigenvalue;  ///< lambda = -zeta omega_n + i omega_d (1/s), Im >= 0
  double naturalFrequency = 0;      ///< omega_n = |lambda| (rad/s)
  double dampedFrequency = 0;       ///< omega_d = Im lambda (rad/s)
  double naturalFrequencyHz = 0;    ///< omega_n / (2 pi)
  double dampedFrequencyHz = 0;     ///< omega_d / (2 pi)
  /// zeta = -Re lambda / |lambda|; negative for an unstable mode; +-1 for a real eigenvalue.
  double dampingRatio = 0;
  /// Logarithmic decrement -2 pi Re lambda / Im lambda = 2 pi zeta / sqrt(1 - zeta^2);
  /// infinite for a real eigenvalue.
  double logDecrement = 0;
  /// The damping ratio the eigensolver's round-off can give this mode in either sign: shift
  /// and invert resolves eigenvalues to a fraction of the one nearest the shift, so a mode far
  /// from it carries more (RotorModes.cpp). What a verdict reads as neutral.
  double roundOff = 0;
  /// Orbit sense at whirlNode. At rest an isotropic rotor's modes are double eigenvalues;
  /// their basis is fixed as circular backward, then forward whirl (DegenerateModes.hpp).
  Whirl whirl = Whirl::planar;
  /// Orbit::whirlRatio at whirlNode.
  double whirlRatio = 0;
  /// The node with the largest orbit (|uy|^2 + |uz|^2), which decides the whirl.
  int whirlNode = -1;
  /// Complex shape, scaled so its largest translation is 1 (real); empty in Campbell results.
  ComplexNodalField shape;
  /// Eigen-solutions that found this mode with whirl-dependent bearings at its own eigenvalue
  /// (fem/rotor/WhirlIteration.hpp); 0 with the synchronous set.
  int whirlIterations = 0;
  /// The share of the mode's energy in the bearings' own dofs (a tilting pad's tilt,
  /// SpeedDependentElement::ownDofs): q_o^H (K_oo + |lambda|^2 M_oo) q_o over the same sum
  /// over every block (K's symmetric part; the blocks of the bearings' own dofs and of the
  /// rotor's). 0 without such dofs; above 0.5 the mode is the bearings' (a pad mode).
  double bearingEnergy = 0;
};

/// Which bearing coefficients the modes were found with: the synchronous set (whirl = spin),
/// or each mode's own (bearings whose coefficients depend on the whirl).
struct WhirlCoefficientsUsed {
  bool atOwnWhirl = false;    ///< each mode at its own eigenvalue
  int mostIterations = 0;     ///< the most eigen-solutions one mode took
  /// Modes that did not settle within kMaxWhirlIterations, or settled on a mode found before
  /// them (they keep the synchronous set's eigenvalue): their sweep speed index (0 for a
  /// single speed) and that eigenvalue's damped frequency (Hz).
  struct Unsettled {
    std::size_t speed = 0;
    double frequencyHz = 0;
  };
  std::vector<Unsettled> unsettled;
  /// Folds another speed's record into this one (speed indices as given).
  void add(const WhirlCoefficientsUsed& other, std::size_t speed);
};

/// Where a mode's energy lies: "rotor", or "pads" (RotorMode::bearingEnergy above 0.5).
inline const char* energyIn(const RotorMode& mode) {
  return mode.bearingEnergy > 0.5 ? "pads" : "rotor";
}

struct RotorModesResult {
  double speed = 0;              ///< spin speed Omega (rad/s)
  std::vector<RotorMode> modes;  ///< nearest the shift first (lowest omega_n for shift 0)
  /// Modes whose energy lies mostly in the bearings' own dofs (tilting pads kept as dofs):
  /// found beside `modes` (one per own dof asked for in addition), not counted among them.
  std::vector<RotorMode> bearingModes;
  /// The same modes as free-dof vectors (DofMap order, columns as modes, unit norm), for
  /// correlation (MAC) and post-processing.
  Eigen::MatrixXcd vectors;
  WhirlCoefficientsUsed coefficients;
  SystemSize size;
  SolveTimings time;
};

/// A step of the sweep where a Campbell line changes mode: its shape correlates less than 0.5
/// with its last (neither a repeated eigenvalue), or its eigenvalue leaves the straight
/// continuation of its last two speeds by more than a quarter of its size, even through a
/// denser local sweep (RotorCampbell.hpp).
/// Its MAC may still read near 1: modes dominated by the same disk's orbit correlate whatever
/// else they do.
struct LineJump {
  int line = -1;
  std::size_t speed = 0;       ///< index of the speed it jumps at (from the one before)
  double fromHz = 0, toHz = 0;  ///< the line's damped frequency before and after
  double mac = 0;              ///< the MAC the tracking gave that step
};

/// A mode the sweep solved that follows none of its lines yet grows: the lines' verdict
/// (stability, onset) does not see it.
struct UntrackedGrowth {
  std::size_t speed = 0;    ///< index of the lowest sweep speed where one grows
  double frequencyHz = 0;   ///< its damped frequency there
  double logDecrement = 0;  ///< < 0 (-inf when it grows without oscillating)
  Whirl whirl = Whirl::planar;
};

/// A Campbell diagram: modes tracked across speeds by eigenvector correlation.
struct CampbellResult {
  std::vector<double> speeds;  ///< rad/s, as given
  /// lines[l][s]: mode l at speeds[s] (no shapes). A line follows one mode through crossings.
  std::vector<std::vector<RotorMode>> lines;
  /// mac[l][s]: MAC between line l's vectors at speeds s - 1 and s (1 at s = 0); a low value
  /// flags a jump the tracking could not resolve (speed step too coarse).
  std::vector<std::vector<double>> mac;
  SystemSize size;
  SolveTimings time;
  int symbolicAnalyses = 0;  ///< sparse symbolic factorisations done (1 when reused)
  /// The most modes solved at one speed (the lines and a margin, more in a local sweep), which
  /// is what a refinement between two speeds solves to find every line again
  int candidates = 0;
  /// Intervals swept again at denser speeds, with more candidates, because a line seemed to
  /// jump across them
  int localSweeps = 0;
  std::vector<LineJump> jumps;  ///< the jumps those sweeps did not cure
  std::optional<UntrackedGrowth> untracked;  ///< the lowest growing mode outside the lines
  WhirlCoefficientsUsed coefficients;  ///< over every speed solved (local sweeps included)
};

/// Where a line's damped frequency crosses the excitation order x speed line.
struct CriticalSpeed {
  int line = -1;
  double order = 1;  ///< the excitation order x speed line it meets
  double speed = 0;  ///< rad/s, linearly interpolated between the bracketing speeds
  double rpm = 0;
  double frequencyHz = 0;       ///< = order * speed / (2 pi)
  double dampingRatio = 0;      ///< interpolated
  Whirl whirl = Whirl::planar;  ///< at the nearer bracketing speed
};

/// Synchronous response to unbalance: u(t) = Re(U e^{i Omega t}) at each speed.
struct UnbalanceResult {
  std::vector<double> speeds;              ///< rad/s
  std::vector<int> nodes;                  ///< the nodes reported
  std::vector<std::vector<Orbit>> orbits;  ///< orbits[k][s]: nodes[k] at speeds[s]
  SystemSize size;
  SolveTimings time;
  int symbolicAnalyses = 0;  ///< sparse symbolic factorisations done (1 when reused)
};

}  // namespace beamrotor

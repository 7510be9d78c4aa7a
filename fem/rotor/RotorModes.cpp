#include "fem/rotor/RotorModes.hpp"

#include <algorithm>
#include <cmath>
#include <complex>
#include <limits>
#include <numbers>
#include <vector>

#include "fem/rotor/DegenerateModes.hpp"
#include "fem/rotor/RotorCampbell.hpp"
#include "fem/rotor/WhirlIteration.hpp"
#include "fem/timing/Stopwatch.hpp"

namespace beamrotor {

namespace {

constexpr double kTwoPi = 2 * std::numbers::pi;
// An orbit whose minor axis is below this fraction of its major is a line: eigenvectors carry
// round-off of ~1e-10 of their largest entry, far below this.
constexpr double kPlanarWhirl = 1e-6;
// A pair of eigenvalues this close to the real axis (relative to |lambda|) is one real
// eigenvalue seen through round-off.
constexpr double kRealEigenvalue = 1e-12;
// Two real eigenvalues lambda and -lambda within this (relative to |lambda|) are one mode. An
// undamped (or only gyroscopic) rotor's spectrum is symmetric under lambda -> -lambda: a
// divergent mode is the pair +-sqrt(k/m) with one shape, and a rigid-body mode's double zero
// (a Jordan block, q = a + b t) splits under round-off into +-delta, imaginary or real. Measured
// on a free-free shaft (10 and 100 elements, shift -100): real mirrors agree to 3e-10, while
// distinct rigid-body eigenvalues there differ by 2e-3 relative.
constexpr double kMirrorPair = 1e-6;
// The damping ratio round-off can give a mode d = |lambda - shift| / |lambda_1 - shift| times
// further from the shift than the nearest mode lambda_1: about 1e-13 d (ARPACK's Ritz values
// nu = 1 / (lambda - shift) err by ~1e-13 of the largest nu) and, for clustered modes far out,
// up to ~1e-16 d^2. Measured on undamped rotors: the bounce and conical modes of a rigid rotor
// (E = 2e17, d ~ 1) 3e-16; its bending modes (d = 4800) 2e-9; a Jeffcott rotor's massless-shaft
// modes (d = 9.2e6) 9.4e-4. The coefficients keep a margin of 25 or more over each.
constexpr double kRoundOffLinear = 1e-11, kRoundOffSquare = 1e-15;

bool isRealEigenvalue(std::complex<double> lambda) {
  return std::abs(lambda.imag()) <= kRealEigenvalue * std::abs(lambda);
}

/// The pairs to report, nearest the shift first, at most `modes`: one per conjugate pair (the
/// member with Im lambda > 0), one per real eigenvalue, and one per real mirror pair (its
/// member with the larger real part, so that a divergent mode stays visible as unstable).
std::vector<int> onePerMode(const std::vector<std::complex<double>>& values, int modes) {
  std::vector<int> kept;
  for (int k = 0; k < int(values.size()) && int(kept.size()) < modes; ++k) {
    const std::complex<double> lambda = values[k];
    if (lambda.imag() < -kRealEigenvalue * std::abs(lambda)) continue;
    if (isRealEigenvalue(lambda)) {
      const auto mirror = std::find_if(kept.begin(), kept.end(), [&](int j) {
        return isRealEigenvalue(values[j]) &&
               std::abs(values[j].real() + lambda.real()) <= kMirrorPair * std::abs(lambda);
      });
      if (mirror != kept.end()) {
        if (lambda.real() > values[*mirror].real()) *mirror = k;
        continue;
      }
    }
    kept.push_back(k);
  }
  return kept;
}

/// Scales q so its largest translation (or, with none moving, its largest entry) is 1.
void normaliseShape(Eigen::VectorXcd& q, const DofMap& dofs) {
  int best = -1;
  for (int eq = 0; eq < int(q.size()); ++eq)
    if (!isRotation(dofs.dofOf(eq).dof) && (best < 0 || std::abs(q[eq]) > std::abs(q[best])))
      best = eq;
  if (best < 0 || std::abs(q[best]) == 0) q.cwiseAbs().maxCoeff(&best);
  if (std::abs(q[best]) > 0) q /= q[best];
}

/// Frequencies, damping and whirl of one eigenpair.
RotorMode describe(std::complex<double> lambda, const Eigen::VectorXcd& q, const DofMap& dofs,
                   int nodeCount) {
  RotorMode mode;
  mode.eigenvalue = lambda;
  mode.naturalFrequency = std::abs(lambda);
  mode.dampedFrequency = lambda.imag();
  mode.naturalFrequencyHz = mode.naturalFrequency / kTwoPi;
  mode.dampedFrequencyHz = mode.dampedFrequency / kTwoPi;
  mode.dampingRatio = mode.naturalFrequency > 0 ? -lambda.real() / mode.naturalFrequency : 0;
  mode.logDecrement = lambda.imag() > 0   ? -kTwoPi * lambda.real() / lambda.imag()
                      : lambda.real() < 0 ? std::numeric_limits<double>::infinity()
                      : lambda.real() > 0 ? -std::numeric_limits<double>::infinity()
                                          : 0.0;
  // The whirl is read at the node with the largest lateral orbit.
  double largest = -1;
  Orbit orbit;
  for (int node = 0; node < nodeCount; ++node) {
    const int y = dofs.equation(node, Dof::uy), z = dofs.equation(node, Dof::uz);
    const Orbit o{dofs.isFree(y) ? q[y] : 0.0, dofs.isFree(z) ? q[z] : 0.0};
    const double size = std::norm(o.uy) + std::norm(o.uz);
    if (size > largest) {
      largest = size;
      orbit = o;
      mode.whirlNode = node;
    }
  }
  mode.whirlRatio = orbit.whirlRatio();
  mode.whirl = lambda.imag() <= 0 || std::abs(mode.whirlRatio) < kPlanarWhirl ? Whirl::planar
               : mode.whirlRatio > 0                                          ? Whirl::forward
                                                                              : Whirl::backward;
  return mode;
}

/// Every mode found again at its own eigenvalue (WhirlIteration.hpp); the eigen-solutions
/// each took. Each mode is tracked from its start (the synchronous set's eigenpair) to its end,
/// and the ends are compared with the starts: a mode keeps its synchronous eigenvalue, and is
/// recorded in `used.unsettled`, when it did not settle, when its shape at the end is no longer
/// the one it started with (MAC below kKeptShape), or when it ends where another mode ends
/// although the two started apart (two starts cannot both be one eigenvalue's mode: the one
/// whose end keeps its start's shape less yields).
std::vector<int> modesAtOwnWhirl(const RotorSystem& system, double speed,
                                 const RotorOptions& options, QuadraticEigenSolver& solver,
                                 std::vector<std::complex<double>>& lambdas,
                                 Eigen::MatrixXcd& vectors, WhirlScope scope,
                                 WhirlCoefficientsUsed& used) {
  // Ends this close (relative) are one eigenvalue; starts farther apart than this were two
  // (a repeated eigenvalue's members start within kRepeatedEigenvalue of each other).
  constexpr double kSameEigenvalue = 1e-8, kApart = 1e-6;
  // A mode's end whose shape correlates less than this with its start has become another mode.
  // Measured on a shaft on two four-pad bearings (test_whirl_dependent_bearings.cpp): the
  // modes that settle on their own end at MAC >= 0.996 against their start; its conical mode,
  // which lands on the bounce pair, at 3e-30. An end that keeps more than this but lands on
  // another mode is caught by the comparison of the ends.
  constexpr double kKeptShape = 0.5;
  used.atOwnWhirl = true;
  const int n = int(lambdas.size());
  std::vector<int> iterations(n, 0);
  std::vector<WhirlMode> ends;
  std::vector<bool> kept(n, false), asked(n, true);
  if (scope.follow && scope.follow->cols() > 0) {
    asked.assign(n, false);
    for (const auto& [candidate, mac] : matchByMac(*scope.follow, vectors)) asked[candidate] = true;
  } else if (scope.first >= 0) {
    for (int m = 0; m < n; ++m) asked[m] = m < scope.first;
  }
  for (int m = 0; m < n; ++m) {
    if (!asked[m]) {
      ends.push_back({lambdas[m], vectors.col(m), 0, false});
      continue;
    }
    ends.push_back(
        modeAtOwnWhirl(system, speed, lambdas[m], vectors.col(m), solver, options.method));
    iterations[m] = ends[m].iterations;
    used.mostIterations = std::max(used.mostIterations, ends[m].iterations);
    kept[m] = ends[m].converged && ends[m].startShape >= kKeptShape;
  }
  for (int a = 0; a < n; ++a)
    for (int b = a + 1; b < n; ++b) {
      if (!kept[a] || !kept[b]) continue;
      const std::complex<double> ea = ends[a].eigenvalue, eb = ends[b].eigenvalue;
      if (std::abs(ea - eb) > kSameEigenvalue * std::abs(ea)) continue;
      if (std::abs(lambdas[a] - lambdas[b]) <= kApart * std::abs(lambdas[a])) continue;
      (ends[a].startShape < ends[b].startShape ? kept[a] : kept[b]) = false;
    }
  for (int m = 0; m < n; ++m) {
    if (!asked[m]) continue;
    if (!kept[m]) {
      used.unsettled.push_back({0, lambdas[m].imag() / kTwoPi});
      continue;
    }
    lambdas[m] = ends[m].eigenvalue;
    vectors.col(m) = ends[m].vector;
  }
  return iterations;
}

/// The share of q's energy in the bearings' own dofs (RotorMode::bearingEnergy): the
/// diagonal blocks of K's symmetric part and of |lambda|^2 M, own dofs against the rotor's.
double bearingEnergyOf(const RotorSystem& system, const SparseMatrix& K, std::complex<double> lambda,
                       const Eigen::VectorXcd& q) {
  const double l2 = std::norm(lambda);
  double own = 0, rotor = 0;
  // Re(conj(q_r) q_c) written out (the complex product's real part, the same bits), and each
  // column's dof kind and entry read once: a pass per mode over K and M, 5 % of the tilting-pad
  // deck's samples before.
  auto add = [&](const SparseMatrix& A, double scale) {
    for (int col = 0; col < A.outerSize(); ++col) {
      const bool ownCol = system.isBearingOwn(col);
      const double cr = q[col].real(), ci = q[col].imag();
      for (SparseMatrix::InnerIterator it(A, col); it; ++it) {
        const int row = int(it.row());
        const bool ownRow = system.isBearingOwn(row);
        if (ownRow != ownCol) continue;  // the coupling blocks
        const double e = scale * it.value() *
                         (q[row].real() * cr + q[row].imag() * ci);  // symmetric part's share
        (ownRow ? own : rotor) += e;
      }
    }
  };
  add(K, 1.0);
  add(system.mass(), l2);
  own = std::abs(own);
  rotor = std::abs(rotor);
  return own + rotor > 0 ? own / (own + rotor) : 0.0;
}

/// The eigenvalues the bearings' own dofs add: one for a dof without mass (a massless pad's
/// first-order relaxation), two for one with mass.
int ownEigenvalues(const RotorSystem& system) {
  if (!system.hasBearingOwnDofs()) return 0;
  int count = 0;
  for (int eq = 0; eq < system.size(); ++eq)
    if (system.isBearingOwn(eq)) count += system.mass().coeff(eq, eq) > 0 ? 2 : 1;
  return count;
}

ComplexNodalField toComplexNodalField(const DofMap& dofs, int nodeCount,
                                      const Eigen::VectorXcd& q) {
  ComplexNodalField field = ComplexNodalField::Zero(nodeCount, kDofKinds);
  for (int eq = 0; eq < int(q.size()); ++eq) {
    const NodeDof& d = dofs.dofOf(eq);
    field(d.node, dofIndex(d.dof)) = q[eq];
  }
  return field;
}

}  // namespace

RotorModesResult solveRotorModes(const RotorSystem& system, double speed,
                                 const RotorOptions& options, QuadraticEigenSolver& solver,
                                 bool shapes, WhirlScope scope) {
  Stopwatch clock, total;
  RotorModesResult result;
  result.speed = speed;

  // 1. The matrices at this speed: D = C(Omega) + Omega G.
  const SparseMatrix K = system.stiffness(speed);
  const SparseMatrix D = system.damping(speed) + speed * system.gyroscopic();
  result.time.assembly = clock.lap();

  // 2. Eigenpairs: a mode is a conjugate pair, so ask for two eigenvalues per mode. Each of
  // the bearings' own dofs (a pad's tilt) brings a mode of its own (a relaxation, or a pair
  // with the pad's inertia): ask for those as well, reported apart.
  // The pads' modes may be pairs as well (energy mostly in the tilts, yet oscillating): when
  // those leave fewer of the rotor's modes than asked, solve again with a pair per tilt.
  const int own = system.bearingOwnCount();
  const int asked = options.modes + own;
  int wanted = 2 * options.modes + ownEigenvalues(system);
  QuadraticEigenpairs pairs;
  for (;;) {
    pairs = solver.solve(K, D, system.mass(), wanted, options.shift, options.method);
    if (own == 0 || wanted >= 2 * asked) break;
    const std::vector<std::complex<double>> found(pairs.values.begin(), pairs.values.end());
    int rotorModes = 0;
    for (int k : onePerMode(found, asked))
      if (bearingEnergyOf(system, K, found[k], pairs.vectors.col(k)) <= 0.5) ++rotorModes;
    if (rotorModes >= options.modes) break;
    wanted = 2 * asked;
  }
  result.time.solve = clock.lap();

  // 3. One mode per conjugate pair, per real eigenvalue and per real mirror pair.
  const DofMap& dofs = system.dofs();
  const int nodes = system.model().nodeCount();
  const std::vector<std::complex<double>> values(pairs.values.begin(), pairs.values.end());
  const std::vector<int> kept = onePerMode(values, asked);
  std::vector<std::complex<double>> lambdas;
  Eigen::MatrixXcd vectors(system.size(), kept.size());
  for (int m = 0; m < int(kept.size()); ++m) {
    lambdas.push_back(pairs.values[kept[m]]);
    vectors.col(m) = pairs.vectors.col(kept[m]);
  }
  // 4. Repeated eigenvalues get a basis fixed by their whirl, not by the solver's start.
  canonicalRepeatedModes(lambdas, vectors, dofs, nodes);
  // 5. Bearings whose coefficients depend on the whirl: each mode at its own eigenvalue.
  std::vector<int> iterations(lambdas.size(), 0);
  if (system.dependsOnWhirl()) {
    iterations = modesAtOwnWhirl(system, speed, options, solver, lambdas, vectors, scope,
                                 result.coefficients);
    // Each member of a repeated pair settles on some vector of its plane: the basis again.
    canonicalRepeatedModes(lambdas, vectors, dofs, nodes);
    result.time.solve += clock.lap();
  }
  double nearest = std::numeric_limits<double>::infinity();
  for (const auto& lambda : lambdas) nearest = std::min(nearest, std::abs(lambda - options.shift));
  result.vectors.resize(system.size(), kept.size());
  int rotorModes = 0;
  for (int m = 0; m < int(kept.size()); ++m) {
    std::complex<double> lambda = lambdas[m];
    Eigen::VectorXcd q = vectors.col(m);
    if (isRealEigenvalue(lambda)) {
      lambda = lambda.real();
      q = q.real().cast<std::complex<double>>();
    }
    normaliseShape(q, dofs);
    RotorMode mode = describe(lambda, q, dofs, nodes);
    mode.whirlIterations = iterations[m];
    const double d =
        nearest > 0 ? std::max(1.0, std::abs(lambda - options.shift) / nearest) : 1.0;
    mode.roundOff = kRoundOffLinear * d + kRoundOffSquare * d * d;
    if (own > 0) mode.bearingEnergy = bearingEnergyOf(system, K, lambda, q);
    if (shapes) mode.shape = toComplexNodalField(dofs, nodes, q);
    if (mode.bearingEnergy > 0.5) {
      result.bearingModes.push_back(std::move(mode));
      continue;
    }
    if (rotorModes == options.modes && !options.everyRotorMode) continue;
    result.vectors.col(rotorModes++) = q / q.norm();
    result.modes.push_back(std::move(mode));
  }
  result.vectors.conservativeResize(Eigen::NoChange, rotorModes);
  result.size = system.systemSize(pairs.factorEntries);
  result.time.total = total.lap();
  return result;
}

RotorModesResult solveRotorModes(const Model& model, double speed, const RotorOptions& options) {
  Stopwatch clock;
  const RotorSystem system(model, options.damping);
  const double assembly = clock.lap();
  QuadraticEigenSolver solver;
  RotorModesResult result = solveRotorModes(system, speed, options, solver);
  result.time.assembly += assembly;
  result.time.total += assembly;
  return result;
}

}  // namespace beamrotor

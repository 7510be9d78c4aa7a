#include "fem/rotor/CriticalSpeedMap.hpp"

#include <algorithm>
#include <cmath>
#include <complex>
#include <string>
#include <utility>
#include <vector>

#include "fem/rotor/BearingSupports.hpp"
#include "fem/rotor/RotorSystem.hpp"
#include "fem/solvers/Errors.hpp"

namespace beamrotor {

namespace {

using Triplets = std::vector<Eigen::Triplet<double>>;

/// Entries of A (rows and columns renumbered by `index`, -1 dropping them) shifted by
/// (rowOffset, colOffset) and scaled, appended to t.
void appendBlock(Triplets& t, const SparseMatrix& A, const std::vector<int>& index, int rowOffset,
                 int colOffset, double scale) {
  for (int col = 0; col < A.outerSize(); ++col)
    for (SparseMatrix::InnerIterator it(A, col); it; ++it)
      if (index[it.row()] >= 0 && index[col] >= 0)
        t.emplace_back(index[it.row()] + rowOffset, index[col] + colOffset, scale * it.value());
}

/// The matrices of the synchronous problem K q0 = Omega^2 (M - i G) q0 over the dofs `index`
/// keeps, in real form (see CriticalSpeedMap.hpp): K2 = [K 0; 0 K], M2 = [M G; -G M].
struct SynchronousProblem {
  SparseMatrix K2, M2;
  int size = 0;                             ///< n, the kept dofs
  std::vector<std::pair<int, int>> planes;  ///< (uy, uz) equations (kept numbering) per node
};

SynchronousProblem synchronousProblem(const SparseMatrix& K, const RotorSystem& system,
                                      const std::vector<int>& index) {
  SynchronousProblem p;
  p.size = int(std::count_if(index.begin(), index.end(), [](int i) { return i >= 0; }));
  const int n = p.size;
  Triplets k, m;
  appendBlock(k, K, index, 0, 0, 1);
  appendBlock(k, K, index, n, n, 1);
  appendBlock(m, system.mass(), index, 0, 0, 1);
  appendBlock(m, system.mass(), index, n, n, 1);
  appendBlock(m, system.gyroscopic(), index, 0, n, 1);
  appendBlock(m, system.gyroscopic(), index, n, 0, -1);
  p.K2.resize(2 * n, 2 * n);
  p.M2.resize(2 * n, 2 * n);
  p.K2.setFromTriplets(k.begin(), k.end());
  p.M2.setFromTriplets(m.begin(), m.end());
  const DofMap& dofs = system.dofs();
  for (int node = 0; node < int(system.model().nodes().size()); ++node) {
    const int y = dofs.equation(node, Dof::uy), z = dofs.equation(node, Dof::uz);
    if (dofs.isFree(y) && dofs.isFree(z) && index[y] >= 0 && index[z] >= 0)
      p.planes.emplace_back(index[y], index[z]);
  }
  return p;
}

/// Whirl of q0 = a + i b over all nodes: (forward - backward) / (forward + backward) of the
/// squared orbit radii |uy +- i uz|^2; +1 forward, -1 backward, 0 planar.
double whirlMeasure(const SynchronousProblem& p, const Eigen::VectorXd& x) {
  const std::complex<double> i(0, 1);
  double forward = 0, backward = 0;
  for (const auto& [y, z] : p.planes) {
    const std::complex<double> uy(x[y], x[p.size + y]), uz(x[z], x[p.size + z]);
    forward += std::norm(uy + i * uz);
    backward += std::norm(uy - i * uz);
  }
  return forward + backward > 0 ? (forward - backward) / (forward + backward) : 0;
}

// Roots closer than this (relative) are one multiple root: the real form doubles each, and a
// model without gyroscopic moments has forward and backward whirl at one speed. ARPACK
// resolves the eigenvalues to ~1e-12 relative.
constexpr double kSameRoot = 1e-8;
// Below this fraction of |lambda| the real part is round-off of an imaginary root.
constexpr double kImaginary = 1e-6;
// A clearly backward shape: forward whirl gives +1, a planar mix of the two about 0.
constexpr double kClearlyBackward = -0.5;

/// The lowest `count` forward synchronous roots (rad/s) at least `floor`, nearest the shift.
std::vector<double> forwardRoots(const SynchronousProblem& p, int count, double shift,
                                 double floor, int extra, EigenMethod method,
                                 QuadraticEigenSolver& solver) {
  const SparseMatrix D(2 * p.size, 2 * p.size);
  const int states = 4 * p.size;
  // Per forward root: two real shapes, each a conjugate pair; as many backward ones.
  int asked = std::min(states, 8 * count + 4 + extra);
  while (true) {
    const QuadraticEigenpairs e = solver.solve(p.K2, D, p.M2, asked, shift, method);
    struct Root {
      double speed, whirl;
    };
    std::vector<Root> roots;
    for (int j = 0; j < int(e.values.size()); ++j) {
      const std::complex<double> lambda = e.values[j];
      // Infinite eigenvalues (a singular M2) and real ones are no critical speeds.
      if (!std::isfinite(std::abs(lambda)) || !(lambda.imag() > floor) ||
          std::abs(lambda.real()) > kImaginary * std::abs(lambda))
        continue;
      // Omega^2 is real, so the real and imaginary parts of the shape are both shapes.
      const Eigen::VectorXcd q = e.vectors.col(j);
      Eigen::VectorXd x = q.real();
      if (q.imag().norm() > x.norm()) x = q.imag();
      roots.push_back({lambda.imag(), whirlMeasure(p, x)});
    }
    std::sort(roots.begin(), roots.end(),
              [](const Root& a, const Root& b) { return a.speed < b.speed; });
    std::vector<double> forward;
    for (std::size_t j = 0; j < roots.size();) {
      std::size_t end = j + 1;
      bool isForward = roots[j].whirl > kClearlyBackward;
      while (end < roots.size() && roots[end].speed - roots[j].speed <= kSameRoot * roots[j].speed)
        isForward = isForward || roots[end++].whirl > kClearlyBackward;
      if (isForward) forward.push_back(roots[j].speed);
      j = end;
    }
    // The last root found may be missing its double: only those below it are complete.
    if (int(forward.size()) > count || asked >= states) {
      if (int(forward.size()) < count)
        throw SolveError("critical-speed map: only " + std::to_string(forward.size()) +
                         " forward critical speeds exist in this model (asked " +
                         std::to_string(count) + ")");
      forward.resize(count);
      return forward;
    }
    asked = std::min(states, 2 * asked);
  }
}

}  // namespace

CriticalSpeedMap solveCriticalSpeedMap(const Model& model, const std::vector<double>& stiffness,
                                       int count, EigenMethod method) {
  const RotorSystem system(model);
  const int n = system.size();
  // 1. The rotor without its bearings, and the bearings' free lateral equations.
  const BearingSupports supports = bearingSupports(system);
  const SparseMatrix& shaft = supports.shaft;
  const std::vector<int> all = numberingWithout(n, {});
  QuadraticEigenSolver solver;
  CriticalSpeedMap out;
  out.stiffness = stiffness;

  // 2. Each stiffness: the shaft plus k on every bearing's uy and uz.
  SparseMatrix unit(n, n);
  {
    Triplets t;
    for (int eq : supports.equations) t.emplace_back(eq, eq, 1.0);
    unit.setFromTriplets(t.begin(), t.end());
  }
  for (double k : stiffness) {
    const SynchronousProblem p = synchronousProblem(shaft + k * unit, system, all);
    out.speeds.push_back(forwardRoots(p, count, 0, 0, 0, method, solver));
  }

  // 3. Pinned bearings: their equations removed.
  out.pinned = forwardRoots(
      synchronousProblem(shaft, system, numberingWithout(n, supports.equations)), count, 0, 0, 0,
      method, solver);

  // 4. Free rotor: K is singular (rigid-body motions, Omega = 0), so the shift lies below the
  // lowest pinned root and roots below 1e-4 of it count as rigid (their computed Omega is
  // round-off of zero, ~1e-8 of the shift).
  const double scale = out.pinned.front();
  constexpr int kRigidStates = 16;  // 4 lateral rigid motions, doubled, each a pair
  out.freeFree = forwardRoots(synchronousProblem(shaft, system, all), count, -0.1 * scale,
                              1e-4 * scale, kRigidStates, method, solver);
  return out;
}

namespace {

/// Line j of the map at stiffness k (inside its range): linear in log k, log Omega.
double lineAt(const CriticalSpeedMap& map, int j, double k) {
  const auto& K = map.stiffness;
  const std::size_t i = std::min<std::size_t>(
      std::upper_bound(K.begin(), K.end(), k) - K.begin(), K.size() - 1);
  const std::size_t a = i == 0 ? 0 : i - 1, b = i == 0 ? 1 : i;
  const double t = std::log(k / K[a]) / std::log(K[b] / K[a]);
  return map.speeds[a][j] * std::pow(map.speeds[b][j] / map.speeds[a][j], t);
}

}  // namespace

std::vector<MapCrossing> mapCrossings(const CriticalSpeedMap& map,
                                      const std::vector<double>& speeds,
                                      const std::vector<double>& stiffness) {
  std::vector<MapCrossing> out;
  if (map.stiffness.size() < 2 || speeds.size() < 2) return out;
  const double kLow = map.stiffness.front(), kHigh = map.stiffness.back();
  const int lines = int(map.speeds.front().size());
  // Between two table rows k is linear in Omega; the crossing is bisected on Omega.
  for (std::size_t r = 0; r + 1 < speeds.size(); ++r) {
    const double w0 = speeds[r], w1 = speeds[r + 1];
    const auto k = [&](double w) {
      return stiffness[r] + (stiffness[r + 1] - stiffness[r]) * (w - w0) / (w1 - w0);
    };
    const auto inside = [&](double w) { return k(w) >= kLow && k(w) <= kHigh; };
    if (!inside(w0) || !inside(w1)) continue;
    for (int j = 0; j < lines; ++j) {
      const auto gap = [&](double w) { return lineAt(map, j, k(w)) - w; };
      double a = w0, b = w1;
      const double ga = gap(a), gb = gap(b);
      if (ga == 0 || !(ga * gb < 0 || gb == 0)) continue;
      if (gb == 0) {
        out.push_back({j, b, k(b)});
        continue;
      }
      for (int it = 0; it < 200 && b - a > 1e-13 * b; ++it) {
        const double mid = (a + b) / 2;
        ((gap(mid) > 0) == (ga > 0) ? a : b) = mid;
      }
      out.push_back({j, (a + b) / 2, k((a + b) / 2)});
    }
  }
  std::sort(out.begin(), out.end(),
            [](const MapCrossing& x, const MapCrossing& y) { return x.speed < y.speed; });
  return out;
}

}  // namespace beamrotor

#include "fem/rotor/CriticalSpeedMap.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>
#include <vector>

#include "fem/rotor/BearingSupports.hpp"
#include "fem/rotor/RotorSystem.hpp"
#include "fem/solvers/Errors.hpp"
#include "fem/solvers/SymmetricEigen.hpp"

namespace beamrotor {

namespace {

/// New numbers of the x-y plane's free equations (uy, rz of every node) that are not in
/// `removed` (ascending): 0, 1, ... in order; -1 for every other equation.
std::vector<int> planeNumbering(const RotorSystem& system, const std::vector<int>& removed) {
  const DofMap& dofs = system.dofs();
  std::vector<char> inPlane(system.size(), 0);
  for (int node = 0; node < int(system.model().nodes().size()); ++node)
    for (Dof d : {Dof::uy, Dof::rz})
      if (const int eq = dofs.equation(node, d); eq >= 0 && dofs.isFree(eq)) inPlane[eq] = 1;
  std::vector<int> index = numberingWithout(system.size(), removed);
  int next = 0;
  for (int i = 0; i < system.size(); ++i) index[i] = inPlane[i] && index[i] >= 0 ? next++ : -1;
  return index;
}

/// The plane's numbering with each pedestal's housing tied to its journal (one equation: the
/// bearing infinitely stiff) and the equations `removed` left out.
std::vector<int> tiedNumbering(const RotorSystem& system, const std::vector<int>& removed,
                               const std::vector<PedestalTie>& ties) {
  std::vector<int> out = removed;
  for (const PedestalTie& t : ties) out.push_back(t.housing);
  std::sort(out.begin(), out.end());
  out.erase(std::unique(out.begin(), out.end()), out.end());
  std::vector<int> index = planeNumbering(system, out);
  for (const PedestalTie& t : ties)
    if (index[t.journal] >= 0) index[t.housing] = index[t.journal];
  return index;
}

/// The housings' equations of the pedestals, ascending.
std::vector<int> housingsOf(const std::vector<PedestalTie>& ties) {
  std::vector<int> out;
  for (const PedestalTie& t : ties) out.push_back(t.housing);
  std::sort(out.begin(), out.end());
  return out;
}

/// A restricted to the equations `index` keeps (renumbered as it says; equations given one
/// number are summed: tied).
SparseMatrix restricted(const SparseMatrix& A, const std::vector<int>& index) {
  const int n = index.empty() ? 0 : *std::max_element(index.begin(), index.end()) + 1;
  std::vector<Eigen::Triplet<double>> t;
  for (int col = 0; col < A.outerSize(); ++col)
    for (SparseMatrix::InnerIterator it(A, col); it; ++it)
      if (index[it.row()] >= 0 && index[col] >= 0)
        t.emplace_back(index[it.row()], index[col], it.value());
  SparseMatrix out(n, n);
  out.setFromTriplets(t.begin(), t.end());
  return out;
}

/// The lowest `count` critical speeds (rad/s) of K q = Omega^2 M q above `floor` (rad/s),
/// Lanczos shifted to `shift` (rad/s)^2 below the spectrum; `skipped` more eigenvalues are
/// asked for, those below the floor (rigid-body modes) being dropped.
std::vector<double> criticalSpeeds(const SparseMatrix& K, const SparseMatrix& M, int count,
                                   double shift, double floor, int skipped) {
  const int asked = std::min<int>(int(K.rows()), count + skipped);
  const EigenPairs e = symmetricEigenpairs(K, M, asked, shift);
  std::vector<double> out;
  for (int j = 0; j < int(e.values.size()) && int(out.size()) < count; ++j)
    if (e.values[j] > floor * floor) out.push_back(std::sqrt(e.values[j]));
  if (int(out.size()) < count)
    throw SolveError("critical-speed map: only " + std::to_string(out.size()) +
                     " critical speeds found in this model (asked " + std::to_string(count) +
                     ")");
  return out;
}

}  // namespace

CriticalSpeedMap solveCriticalSpeedMap(const Model& model, const std::vector<double>& stiffness,
                                       int count) {
  const RotorSystem system(model);
  const int n = system.size();
  // 1. The rotor without its bearings, and the bearings' free lateral equations; the x-y plane.
  const BearingSupports supports = bearingSupports(system, true);
  const std::vector<int> plane = planeNumbering(system, {});
  const SparseMatrix shaft = restricted(supports.shaft, plane);
  const SparseMatrix mass = restricted(system.mass(), plane);
  CriticalSpeedMap out;
  out.stiffness = stiffness;

  // 2. Each stiffness: the shaft plus k on every bearing's uy; on a pedestal, k between journal
  // and housing, in series with the pedestal's own springs.
  SparseMatrix unit(n, n);
  {
    std::vector<Eigen::Triplet<double>> t;
    for (int eq : supports.equations) t.emplace_back(eq, eq, 1.0);
    for (const PedestalTie& p : supports.pedestals) {
      t.emplace_back(p.journal, p.journal, 1.0);
      t.emplace_back(p.housing, p.housing, 1.0);
      t.emplace_back(p.journal, p.housing, -1.0);
      t.emplace_back(p.housing, p.journal, -1.0);
    }
    unit.setFromTriplets(t.begin(), t.end());
  }
  const SparseMatrix springs = restricted(unit, plane);
  for (double k : stiffness) {
    // K + k S is positive definite for k > 0 (the bearings hold the rigid-body motions).
    const SparseMatrix Kk = shaft + k * springs;
    out.speeds.push_back(criticalSpeeds(Kk, mass, count, 0, 0, 0));
  }

  // 3. Pinned bearings: their equations removed; a bearing on a pedestal ties the journal to
  // its housing (the rotor on its pedestals).
  const std::vector<int> pinned = tiedNumbering(system, supports.equations, supports.pedestals);
  out.pinned = criticalSpeeds(restricted(supports.shaft, pinned),
                              restricted(system.mass(), pinned), count, 0, 0, 0);

  // 4. Free rotor: K is singular (two rigid-body motions in the plane, Omega = 0), so the shift
  // lies below them, at -(0.1 Omega_1,pinned)^2; eigenvalues below (1e-4 Omega_1,pinned)^2 are
  // rigid (their computed value is round-off of zero, ~1e-12 of the shift).
  // The housings on their pedestals, cut from the rotor, are no rotor's modes: left out.
  const double scale = out.pinned.front();
  constexpr int kRigidModes = 2;
  const std::vector<int> rotorOnly = planeNumbering(system, housingsOf(supports.pedestals));
  out.freeFree = criticalSpeeds(restricted(supports.shaft, rotorOnly),
                                restricted(system.mass(), rotorOnly), count,
                                -0.01 * scale * scale, 1e-4 * scale, kRigidModes);
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

double rigidSupportCriticalSpeed(const Model& model, double speed) {
  const RotorSystem system(model);
  const DofMap& dofs = system.dofs();
  // The pinned equations: the free uy, uz of each bearing that is stiff at this speed. A
  // bearing on a pedestal pins its journal the same way, and its housing (uy, uz) leaves the
  // rotor with the pedestal's mass and springs: rigid supports are rigid down to the ground.
  std::vector<int> pinned;
  bool bearings = false;
  for (const auto& e : model.elements()) {
    const SpeedDependentElement* pedestalBearing = asBearingOnPedestal(*e);
    const bool onPedestal = pedestalBearing != nullptr;
    const SpeedDependentElement* b = onPedestal ? pedestalBearing : asBearing(*e);
    if (!b) continue;
    bearings = true;
    const auto d = b->dofs();  // journal uy, uz; on a pedestal then housing uy, uz
    const ElementMatrix k = b->stiffnessAt(speed);
    for (int r = 0; r < int(d.size()); ++r)
      if (const int eq = dofs.equation(d[r]);
          eq >= 0 && dofs.isFree(eq) && (k(r, r) != 0 || (onPedestal && r >= 2)))
        pinned.push_back(eq);
  }
  std::sort(pinned.begin(), pinned.end());
  pinned.erase(std::unique(pinned.begin(), pinned.end()), pinned.end());
  // Without the bearings' own stiffness (the pinned ones hold their nodes; the others have none
  // on the diagonal, and a cross-coupled term would make K unsymmetric).
  const SparseMatrix shaft =
      bearings ? bearingSupports(system, /*pedestals=*/true).shaft : system.stiffness(0);
  const std::vector<int> plane = planeNumbering(system, pinned);
  try {
    return criticalSpeeds(restricted(shaft, plane), restricted(system.mass(), plane), 1, 0,
                          0, 0)
        .front();
  } catch (const SolveError&) {
    throw std::invalid_argument(
        "the critical speed on rigid supports: the bearings and supports do not hold the rotor");
  }
}

}  // namespace beamrotor

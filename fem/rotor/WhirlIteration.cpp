#include "fem/rotor/WhirlIteration.hpp"

#include <algorithm>
#include <cmath>
#include <optional>
#include <utility>
#include <vector>

#include "fem/rotor/DegenerateModes.hpp"

namespace beamrotor {

namespace {

/// The shift sits this far (relative, across the real axis) beside the last eigenvalue: near
/// enough that the mode is the nearest eigenvalue once it has settled, far enough that
/// K + sigma D + sigma^2 M stays regular (rcond ~ 1e-6 against kSingularRcond = 1e-14).
constexpr double kShiftOffset = 1e-6;
/// Eigenvalues asked for around the shift: the mode and its conjugate, and a second mode (a
/// nearly repeated one, the other whirl of an isotropic rotor's pair) to tell it from.
constexpr int kAround = 4;
/// A real eigenvalue's imaginary part from the eigensolver, relative: round-off of ~1e-12,
/// more for a real eigenvalue among close complex ones.
constexpr double kRealRoundOff = 1e-8;

/// |a^H b|^2 / (|a|^2 |b|^2).
double correlation(const Eigen::VectorXcd& a, const Eigen::VectorXcd& b) {
  const double den = a.squaredNorm() * b.squaredNorm();
  return den > 0 ? std::norm(a.dot(b)) / den : 0.0;
}

}  // namespace

namespace {

/// The eigenpair of the problem with the coefficients frozen at `at` that is the mode that
/// started with vector `start` and last had vector `q`: of the eigenvalues near `at`, the one
/// whose shape correlates best with the start (ties: the nearest `at`); on the real axis only
/// for an overdamped mode (`real`); none when no candidate qualifies.
std::optional<std::pair<std::complex<double>, Eigen::VectorXcd>> frozenMode(
    const RotorSystem& system, double speed, std::complex<double> at, const Eigen::VectorXcd& start,
    const Eigen::VectorXcd& q, bool real, QuadraticEigenSolver& solver, EigenMethod method) {
  const SparseMatrix K = system.stiffness(speed, at);
  const SparseMatrix D = system.damping(speed, at) + speed * system.gyroscopic();
  const double scale = std::max({std::abs(at), speed, 1.0});
  const std::complex<double> shift = at + std::complex<double>(0, kShiftOffset * scale);
  const QuadraticEigenpairs pairs = solver.solve(K, D, system.mass(), kAround, shift, method);
  int best = -1;
  double bestMac = -1;
  for (int k = 0; k < int(pairs.values.size()); ++k) {
    const std::complex<double> v = pairs.values[k];
    // A real eigenvalue (an overdamped mode) comes back with Im of round-off either sign.
    const bool onAxis = std::abs(v.imag()) <= kRealRoundOff * std::abs(v);
    if (real ? !onAxis : v.imag() < -kRealRoundOff * std::abs(v)) continue;
    const double m = correlation(start, pairs.vectors.col(k));
    if (m > bestMac + 1e-9 || (best >= 0 && std::abs(m - bestMac) <= 1e-9 &&
                               std::abs(v - at) < std::abs(pairs.values[best] - at))) {
      best = k;
      bestMac = m;
    }
  }
  if (best < 0) return std::nullopt;
  std::complex<double> lambda = pairs.values[best];
  if (real) lambda = lambda.real();
  // A repeated eigenvalue (both whirls of an isotropic rotor) has a plane of vectors: the
  // mode keeps its own, the last vector projected onto that plane.
  std::vector<int> same;
  for (int k = 0; k < int(pairs.values.size()); ++k)
    if (std::abs(pairs.values[k] - lambda) <= kRepeatedEigenvalue * std::abs(lambda))
      same.push_back(k);
  Eigen::MatrixXcd plane(pairs.vectors.rows(), Eigen::Index(same.size()));
  for (std::size_t k = 0; k < same.size(); ++k)
    plane.col(Eigen::Index(k)) = pairs.vectors.col(same[k]);
  const Eigen::VectorXcd own = plane * plane.colPivHouseholderQr().solve(q);
  return std::pair{lambda, own.norm() > 1e-3 ? own.normalized()
                                             : Eigen::VectorXcd(pairs.vectors.col(best).normalized())};
}

}  // namespace

WhirlMode modeAtOwnWhirl(const RotorSystem& system, double speed, std::complex<double> lambda,
                         const Eigen::VectorXcd& q, QuadraticEigenSolver& solver,
                         EigenMethod method, double tolerance) {
  // f(at) = g(at) - at, g the frozen problem's eigenvalue: a fixed point of g is a root of f.
  // Secant steps on f (superlinear where the coefficients are smooth in lambda), a plain
  // fixed-point step at the start and wherever the secant would not shrink |f|. An overdamped
  // mode (a real eigenvalue) stays on the real axis, among the real eigenvalues.
  const bool real = std::abs(lambda.imag()) <= kRealRoundOff * std::abs(lambda);
  const Eigen::VectorXcd start = q.normalized();
  WhirlMode out{lambda, start, 0, false};
  std::complex<double> at = real ? std::complex<double>(lambda.real()) : lambda;
  std::complex<double> previousAt = 0, previousF = 0;
  bool havePrevious = false;
  while (out.iterations < kMaxWhirlIterations) {
    const auto frozen = frozenMode(system, speed, at, start, out.vector, real, solver, method);
    ++out.iterations;
    if (!frozen) break;  // no candidate on the mode's side of the real axis (or on it)
    out.eigenvalue = frozen->first;
    out.vector = frozen->second;
    const std::complex<double> f = frozen->first - at;
    if (std::abs(f) <= tolerance * std::abs(frozen->first)) {
      out.converged = true;
      break;
    }
    std::complex<double> next = frozen->first;  // the fixed-point step
    if (havePrevious && std::abs(f) < std::abs(previousF) && f != previousF) {
      const std::complex<double> secant = at - f * (at - previousAt) / (f - previousF);
      if (std::isfinite(secant.real()) && std::isfinite(secant.imag())) next = secant;
    }
    previousAt = at;
    previousF = f;
    havePrevious = true;
    at = real ? std::complex<double>(next.real()) : next;
  }
  out.startShape = correlation(start, out.vector);
  return out;
}

}  // namespace beamrotor

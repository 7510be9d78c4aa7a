#include "fem/rotor/RotorCampbell.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>

#include "fem/solvers/Errors.hpp"
#include "fem/timing/Stopwatch.hpp"

namespace beamrotor {

namespace {

/// Assigns lines to candidates by descending MAC (greedy: take the best remaining pair);
/// returns the candidate of each line and its MAC.
std::vector<std::pair<int, double>> match(const Eigen::MatrixXcd& lines,
                                          const Eigen::MatrixXcd& candidates) {
  const int nl = int(lines.cols()), nc = int(candidates.cols());
  Eigen::MatrixXd table = macTable(lines, candidates);
  std::vector<std::pair<int, double>> out(nl, {-1, 0.0});
  for (int k = 0; k < std::min(nl, nc); ++k) {
    Eigen::Index l = 0, c = 0;
    const double best = table.maxCoeff(&l, &c);
    out[l] = {int(c), best};
    table.row(l).setConstant(-1);
    table.col(c).setConstant(-1);
  }
  return out;
}

}  // namespace

Eigen::MatrixXd macTable(const Eigen::MatrixXcd& a, const Eigen::MatrixXcd& b) {
  // One product for every a_k^H b_l (a sweep's lines against its candidates: 12 x 16
  // columns of 3204 entries at 800 elements), each column's norm once.
  const Eigen::MatrixXcd overlap = a.adjoint() * b;
  const Eigen::VectorXd na = a.colwise().squaredNorm(), nb = b.colwise().squaredNorm();
  Eigen::MatrixXd table(a.cols(), b.cols());
  for (Eigen::Index k = 0; k < a.cols(); ++k)
    for (Eigen::Index l = 0; l < b.cols(); ++l) {
      const double den = na[k] * nb[l];
      table(k, l) = den > 0 ? std::norm(overlap(k, l)) / den : 0.0;
    }
  return table;
}

double mac(const Eigen::VectorXcd& a, const Eigen::VectorXcd& b) { return macTable(a, b)(0, 0); }

int candidatesAtGap(const std::vector<RotorMode>& modes, int lines, std::complex<double> shift) {
  const int widest = int(modes.size());
  int best = widest;
  double widestGap = 0;
  for (int c = lines + std::max(2, lines / 4); c < widest; ++c) {
    const double gap = std::abs(modes[c].eigenvalue - shift) /
                       std::abs(modes[c - 1].eigenvalue - shift);
    if (gap > widestGap) {
      widestGap = gap;
      best = c;
    }
  }
  return best;
}

CampbellResult solveCampbell(const Model& model, const std::vector<double>& speeds,
                             const RotorOptions& options) {
  Stopwatch clock, total;
  CampbellResult result;
  result.speeds = speeds;
  const RotorSystem system(model, options.damping);
  result.time.assembly = clock.lap();
  if (speeds.empty() || options.modes <= 0) return result;

  // Candidates per speed: the asked-for modes plus a margin for reordering; after the first
  // speed the margin ends at the widest gap of the spectrum there (candidatesAtGap).
  const int lines = options.modes;
  RotorOptions wider = options;
  wider.modes = lines + std::max(2, lines / 2);
  QuadraticEigenSolver solver;
  result.lines.assign(lines, {});
  result.mac.assign(lines, {});
  Eigen::MatrixXcd previous;  // each line's vector at the previous speed
  for (std::size_t s = 0; s < speeds.size(); ++s) {
    RotorModesResult at = solveRotorModes(system, speeds[s], wider, solver, false);
    result.time.assembly += at.time.assembly;
    result.time.solve += at.time.solve;
    result.size = at.size;
    const int found = int(at.modes.size());
    if (found < lines)
      throw SolveError("Campbell diagram: only " + std::to_string(found) + " modes found at " +
                       std::to_string(speeds[s]) + " rad/s, " + std::to_string(lines) +
                       " asked for");
    // 1. The first speed defines the lines (nearest the shift first); later speeds follow
    //    each line to the candidate whose shape correlates best with its last one.
    std::vector<std::pair<int, double>> pick(lines);
    if (s == 0)
      for (int l = 0; l < lines; ++l) pick[l] = {l, 1.0};
    else
      pick = match(previous, at.vectors);
    Eigen::MatrixXcd next(at.vectors.rows(), lines);
    for (int l = 0; l < lines; ++l) {
      result.lines[l].push_back(at.modes[pick[l].first]);
      result.mac[l].push_back(pick[l].second);
      next.col(l) = at.vectors.col(pick[l].first);
    }
    previous = std::move(next);
    if (s == 0) wider.modes = candidatesAtGap(at.modes, lines, options.shift);
  }
  result.symbolicAnalyses = solver.analyses();
  result.time.total = total.lap();
  return result;
}

std::vector<CriticalSpeed> criticalSpeeds(const CampbellResult& campbell, double order) {
  std::vector<CriticalSpeed> out;
  const auto& speeds = campbell.speeds;
  for (int l = 0; l < int(campbell.lines.size()); ++l) {
    const auto& line = campbell.lines[l];
    for (std::size_t s = 0; s + 1 < line.size(); ++s) {
      const double f0 = line[s].dampedFrequency - order * speeds[s];
      const double f1 = line[s + 1].dampedFrequency - order * speeds[s + 1];
      // A sign change of (omega_d - order Omega) brackets a crossing; an exact zero belongs
      // to the interval it starts (the last point to the last interval). A zero at the first
      // speed is a zero frequency at rest, not a resonance.
      const bool last = s + 2 == line.size();
      if (!(f0 * f1 < 0 || (f0 == 0 && s > 0) || (last && f1 == 0))) continue;
      const double t = f0 == f1 ? 0 : f0 / (f0 - f1);
      CriticalSpeed c;
      c.line = l;
      c.order = order;
      c.speed = speeds[s] + t * (speeds[s + 1] - speeds[s]);
      c.rpm = c.speed * 60 / (2 * std::numbers::pi);
      c.frequencyHz = order * c.speed / (2 * std::numbers::pi);
      c.dampingRatio = (1 - t) * line[s].dampingRatio + t * line[s + 1].dampingRatio;
      c.whirl = (t < 0.5 ? line[s] : line[s + 1]).whirl;
      out.push_back(c);
    }
  }
  std::sort(out.begin(), out.end(),
            [](const CriticalSpeed& a, const CriticalSpeed& b) { return a.speed < b.speed; });
  return out;
}

}  // namespace beamrotor

#include "fem/rotor/RotorCampbell.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>

#include "fem/rotor/RotorStability.hpp"
#include "fem/solvers/Errors.hpp"
#include "fem/timing/Stopwatch.hpp"

namespace beamrotor {

namespace {

/// Speeds of a local sweep across one interval where a line seems to jump.
constexpr int kLocalSteps = 8;
/// A line's eigenvalue further than this fraction of its size from the straight continuation
/// of its last two speeds has changed mode. A mode's own eigenvalue, continued from two
/// speeds, errs by the curvature of its line times the step squared: a few per cent of its
/// size on a coarse sweep (measured: 7 % for a journal rotor's whirl at its first speeds, whose
/// bearings stiffen fastest there); a line that changes mode moves by the distance between two
/// modes (48 % in issue 42's jump from 98.7 to 47.7 Hz). A false alarm costs one local sweep.
constexpr double kJump = 0.25;
/// A step whose shapes correlate less than this has lost the line's mode (modes of different
/// parts of a machine are orthogonal: MAC near 0; a mode's own shape changes little in one
/// step), unless one end is a repeated eigenvalue, whose basis, and so its MAC, is arbitrary
/// (the conical pair of a rotor at rest correlates 0.5 with its split at the next speed).
/// The MAC alone misses a line that lands on a mode of the same disk (near 1 whatever else
/// the modes do), which the eigenvalue's continuation catches.
constexpr double kLostShape = 0.5;
/// Eigenvalues this close (relative) are one repeated eigenvalue to the MAC: nearly repeated
/// modes (slightly anisotropic bearings at rest) turn their basis within a step as well.
constexpr double kRepeated = 1e-3;
/// Two eigenvalues this close (relative) are the same mode solved twice.
constexpr double kSameMode = 1e-8;

/// One point of a line: a speed, the line's eigenvalue there and whether another candidate
/// there shares it (a NaN speed: no point, the line's first speed having none before it).
struct LinePoint {
  double speed = std::nan("");
  std::complex<double> eigenvalue;
  bool repeated = false;
};

/// Whether candidate c's eigenvalue is repeated among `modes` (kRepeated).
bool isRepeated(const std::vector<RotorMode>& modes, int c) {
  for (int o = 0; o < int(modes.size()); ++o)
    if (o != c && std::abs(modes[o].eigenvalue - modes[c].eigenvalue) <=
                      kRepeated * std::abs(modes[c].eigenvalue))
      return true;
  return false;
}

/// Line l's point at a tracked speed.
LinePoint pointOf(double speed, const RotorModesResult& at, int candidate) {
  return {speed, at.modes[candidate].eigenvalue, isRepeated(at.modes, candidate)};
}

/// Whether `next`, reached with shapes correlating `mac`, leaves the line through `before`
/// and `last`: a low MAC between modes that are not repeated, or an eigenvalue off the
/// straight continuation of the two.
bool jumps(const LinePoint& before, const LinePoint& last, const LinePoint& next, double mac) {
  if (mac < kLostShape && !last.repeated && !next.repeated) return true;
  if (!(last.speed > before.speed)) return false;  // one point: no continuation to leave
  const double t = (next.speed - last.speed) / (last.speed - before.speed);
  const std::complex<double> expected =
      last.eigenvalue + t * (last.eigenvalue - before.eigenvalue);
  return std::abs(next.eigenvalue - expected) >
         kJump * std::max(std::abs(expected), std::abs(last.eigenvalue));
}

/// One speed of a sweep: its candidates and the candidate each line takes (with its MAC).
struct TrackedSpeed {
  RotorModesResult at;
  std::vector<std::pair<int, double>> pick;
};

/// The lines' last two points: at the sweep speeds s - 2 (none for s = 1) and s - 1.
struct LineHistory {
  std::vector<LinePoint> before, last;
};

/// `lastRepeated`: whether each line's eigenvalue was repeated at speed s - 1.
LineHistory historyBefore(const CampbellResult& result, std::size_t s,
                          const std::vector<bool>& lastRepeated) {
  LineHistory h;
  for (std::size_t l = 0; l < result.lines.size(); ++l) {
    const auto& line = result.lines[l];
    h.before.push_back(s >= 2 ? LinePoint{result.speeds[s - 2], line[s - 2].eigenvalue, false}
                              : LinePoint{});
    h.last.push_back({result.speeds[s - 1], line[s - 1].eigenvalue, lastRepeated[l]});
  }
  return h;
}

/// The lines that seem to jump at `speed` (their speed index left for the caller).
std::vector<LineJump> jumpsAt(const LineHistory& h, double speed, const TrackedSpeed& t) {
  std::vector<LineJump> out;
  for (std::size_t l = 0; l < h.last.size(); ++l) {
    const auto& [candidate, mac] = t.pick[l];
    if (!jumps(h.before[l], h.last[l], pointOf(speed, t.at, candidate), mac)) continue;
    LineJump j;
    j.line = int(l);
    j.fromHz = h.last[l].eigenvalue.imag() / (2 * std::numbers::pi);
    j.toHz = t.at.modes[candidate].dampedFrequencyHz;
    j.mac = mac;
    out.push_back(j);
  }
  return out;
}

/// Whether two trackings of one speed give every line the same mode.
bool sameModes(const TrackedSpeed& a, const TrackedSpeed& b) {
  for (std::size_t l = 0; l < a.pick.size(); ++l) {
    const auto x = a.at.modes[a.pick[l].first].eigenvalue;
    const auto y = b.at.modes[b.pick[l].first].eigenvalue;
    if (std::abs(x - y) > kSameMode * std::abs(x)) return false;
  }
  return true;
}

/// Solves the modes of a sweep, counting its time into the result's.
class SweepSolver {
 public:
  SweepSolver(const Model& model, const RotorOptions& options, CampbellResult& result)
      : system_(model, options.damping), options_(options), result_(result) {}

  /// `scope`: the lines' vectors at the last speed (or, at the first, how many lines), so
  /// that only the candidates the lines follow are found at their own eigenvalue.
  RotorModesResult solve(double speed, int candidates, WhirlScope scope) {
    RotorOptions o = options_;
    o.modes = candidates;
    o.everyRotorMode = true;
    RotorModesResult at = solveRotorModes(system_, speed, o, solver_, false, scope);
    result_.time.assembly += at.time.assembly;
    result_.time.solve += at.time.solve;
    result_.size = at.size;
    result_.candidates = std::max(result_.candidates, candidates);
    result_.coefficients.add(at.coefficients, sweepIndex_);
    const int lines = options_.modes;
    if (int(at.modes.size()) < lines)
      throw SolveError("Campbell diagram: only " + std::to_string(at.modes.size()) +
                       " modes found at " + std::to_string(speed) + " rad/s, " +
                       std::to_string(lines) + " asked for");
    return at;
  }
  int analyses() const { return solver_.analyses(); }
  /// The sweep speed index the next solutions belong to (a local sweep's: its interval's end).
  void atSweepIndex(std::size_t s) { sweepIndex_ = s; }

 private:
  RotorSystem system_;
  RotorOptions options_;
  CampbellResult& result_;
  QuadraticEigenSolver solver_;
  std::size_t sweepIndex_ = 0;
};

/// The lines followed from `from` (their vectors there, and their history) to `to` through
/// kLocalSteps equal steps, each solved with `candidates` modes: the tracking at `to`, and
/// each line's first jump on the way (the line index set; speed left for the caller).
TrackedSpeed sweepLocally(SweepSolver& solver, double from, double to, Eigen::MatrixXcd vectors,
                          LineHistory h, int candidates, std::vector<LineJump>& jumped) {
  TrackedSpeed t;
  const std::size_t lines = h.last.size();
  std::vector<bool> seen(lines, false);
  for (int k = 1; k <= kLocalSteps; ++k) {
    const double speed = from + (to - from) * k / kLocalSteps;
    t.at = solver.solve(speed, candidates, {&vectors});
    t.pick = matchByMac(vectors, t.at.vectors);
    Eigen::MatrixXcd next(t.at.vectors.rows(), Eigen::Index(lines));
    for (std::size_t l = 0; l < lines; ++l) {
      const RotorMode& m = t.at.modes[t.pick[l].first];
      const LinePoint point = pointOf(speed, t.at, t.pick[l].first);
      if (!seen[l] && jumps(h.before[l], h.last[l], point, t.pick[l].second)) {
        seen[l] = true;
        LineJump j;
        j.line = int(l);
        j.fromHz = h.last[l].eigenvalue.imag() / (2 * std::numbers::pi);
        j.toHz = m.dampedFrequencyHz;
        j.mac = t.pick[l].second;
        jumped.push_back(j);
      }
      h.before[l] = h.last[l];
      h.last[l] = point;
      next.col(Eigen::Index(l)) = t.at.vectors.col(t.pick[l].first);
    }
    vectors = std::move(next);
  }
  return t;
}

}  // namespace

std::vector<std::pair<int, double>> matchByMac(const Eigen::MatrixXcd& lines,
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

int firstCandidates(int lines) { return lines + std::max(2, lines / 2); }

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
  SweepSolver solver(model, options, result);
  result.time.assembly = clock.lap();
  if (speeds.empty() || options.modes <= 0) return result;

  // Candidates per speed: the asked-for modes plus a margin for reordering; after the first
  // speed the margin ends at the widest gap of the spectrum there (candidatesAtGap).
  const int lines = options.modes;
  int candidates = firstCandidates(lines);
  result.lines.assign(lines, {});
  result.mac.assign(lines, {});
  Eigen::MatrixXcd previous;  // each line's vector at the previous speed
  std::vector<bool> repeated(lines, false);  // whether its eigenvalue was repeated there
  for (std::size_t s = 0; s < speeds.size(); ++s) {
    // 1. The first speed defines the lines (nearest the shift first); later speeds follow
    //    each line to the candidate whose shape correlates best with its last one.
    solver.atSweepIndex(s);
    const WhirlScope scope = s == 0 ? WhirlScope{nullptr, lines} : WhirlScope{&previous};
    TrackedSpeed t{solver.solve(speeds[s], candidates, scope), {}};
    if (s == 0) {
      for (int l = 0; l < lines; ++l) t.pick.push_back({l, 1.0});
      // The gap among the candidates asked for (with pad tilts the speed holds more).
      const std::size_t first = std::min(t.at.modes.size(), std::size_t(candidates));
      const std::vector<RotorMode> asked(t.at.modes.begin(),
                                         t.at.modes.begin() + std::ptrdiff_t(first));
      candidates = candidatesAtGap(asked, lines, options.shift);
    } else {
      t.pick = matchByMac(previous, t.at.vectors);
    }
    // 2. A line that seems to jump: the interval again, densely and with more candidates.
    std::vector<LineJump> jumped;
    if (s >= 1) jumped = jumpsAt(historyBefore(result, s, repeated), speeds[s], t);
    if (!jumped.empty()) {
      ++result.localSweeps;
      const int wider = 2 * candidates;
      const std::vector<LineJump> coarse = std::move(jumped);
      jumped.clear();
      try {
        TrackedSpeed local = sweepLocally(solver, speeds[s - 1], speeds[s], previous,
                                          historyBefore(result, s, repeated), wider, jumped);
        if (!sameModes(t, local)) {
          // A line found its own mode among the wider candidates: keep them from here on.
          for (const auto& [candidate, m] : local.pick)
            if (candidate >= candidates) candidates = wider;
          t = std::move(local);
        }
      } catch (const SolveError&) {
        // The eigensolver gave up on a speed of the local sweep (with many candidates on a
        // badly scaled model): the sweep's own tracking stands, its jumps reported.
        jumped = coarse;
      }
      for (LineJump& j : jumped) {
        j.speed = s;
        result.jumps.push_back(j);
      }
    }
    Eigen::MatrixXcd next(t.at.vectors.rows(), lines);
    std::vector<bool> followed(t.at.modes.size(), false);
    for (int l = 0; l < lines; ++l) {
      const int c = t.pick[l].first;
      result.lines[l].push_back(t.at.modes[c]);
      result.mac[l].push_back(t.pick[l].second);
      next.col(l) = t.at.vectors.col(c);
      followed[c] = true;
      repeated[l] = isRepeated(t.at.modes, c);
    }
    previous = std::move(next);
    // 3. A growing mode no line follows. With whirl-dependent bearings a candidate no line
    //    follows keeps the synchronous set's eigenvalue (WhirlScope), which is not the model's:
    //    its growth says nothing (a massless shaft's numerically infinite eigenvalues, for one).
    const bool ownWhirl = t.at.coefficients.atOwnWhirl;
    for (std::size_t c = 0; c < t.at.modes.size() && !result.untracked; ++c)
      if (!followed[c] && !(ownWhirl && t.at.modes[c].whirlIterations == 0) &&
          growthRate(t.at.modes[c]) > 0) {
        const RotorMode& m = t.at.modes[c];
        result.untracked = UntrackedGrowth{s, m.dampedFrequencyHz, m.logDecrement, m.whirl};
      }
  }
  result.symbolicAnalyses = solver.analyses();
  result.time.total = total.lap();
  return result;
}

std::vector<CrossingBracket> crossingBrackets(const CampbellResult& campbell, double order) {
  std::vector<CrossingBracket> out;
  const auto& speeds = campbell.speeds;
  for (int l = 0; l < int(campbell.lines.size()); ++l) {
    const auto& line = campbell.lines[l];
    for (std::size_t s = 0; s + 1 < line.size(); ++s) {
      const double f0 = line[s].dampedFrequency - order * speeds[s];
      const double f1 = line[s + 1].dampedFrequency - order * speeds[s + 1];
      const bool last = s + 2 == line.size();
      if (!(f0 * f1 < 0 || (f0 == 0 && s > 0) || (last && f1 == 0))) continue;
      out.push_back({l, s, f0 == f1 ? 0 : f0 / (f0 - f1)});
    }
  }
  return out;
}

void sortCriticalSpeeds(std::vector<CriticalSpeed>& speeds) {
  // Two crossings within this (relative) are one speed: the refinement's tolerance, 1e-10,
  // with room for the two lines' round-off.
  constexpr double kSameSpeed = 1e-8;
  const auto rank = [](Whirl w) { return w == Whirl::forward ? 0 : w == Whirl::planar ? 1 : 2; };
  std::sort(speeds.begin(), speeds.end(),
            [](const CriticalSpeed& a, const CriticalSpeed& b) { return a.speed < b.speed; });
  for (auto group = speeds.begin(); group != speeds.end();) {
    auto end = group + 1;
    while (end != speeds.end() && end->speed - group->speed <= kSameSpeed * std::abs(end->speed))
      ++end;
    std::stable_sort(group, end, [&](const CriticalSpeed& a, const CriticalSpeed& b) {
      return rank(a.whirl) < rank(b.whirl);
    });
    group = end;
  }
}

std::vector<CriticalSpeed> criticalSpeeds(const CampbellResult& campbell, double order) {
  std::vector<CriticalSpeed> out;
  const auto& speeds = campbell.speeds;
  for (const CrossingBracket& b : crossingBrackets(campbell, order)) {
    const auto& line = campbell.lines[b.line];
    const std::size_t s = b.interval;
    const double t = b.t;
    CriticalSpeed c;
    c.line = b.line;
    c.order = order;
    c.speed = speeds[s] + t * (speeds[s + 1] - speeds[s]);
    c.rpm = c.speed * 60 / (2 * std::numbers::pi);
    c.frequencyHz = order * c.speed / (2 * std::numbers::pi);
    c.dampingRatio = (1 - t) * line[s].dampingRatio + t * line[s + 1].dampingRatio;
    c.whirl = (t < 0.5 ? line[s] : line[s + 1]).whirl;
    out.push_back(c);
  }
  sortCriticalSpeeds(out);
  return out;
}

}  // namespace beamrotor

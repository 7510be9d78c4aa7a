#include "elements/ReynoldsFilm.hpp"

#include <Eigen/Sparse>
#include <Eigen/SparseCholesky>
#include <array>
#include <cmath>
#include <stdexcept>
#include <vector>

namespace beamrotor {

namespace {

constexpr double kPiArc = std::numbers::pi;

using FilmMatrix = Eigen::SparseMatrix<double>;
using FilmVector = Eigen::VectorXd;

/// The discrete film: finite volumes centred on the nodes theta_i = start + i dtheta
/// (i = 1 .. n - 1; the arc's edges, nodes 0 and n, hold P = 0) and zeta_j = j dzeta
/// (j = 0 .. m - 1; the end, j = m, holds P = 0; the mid-plane cell is half a cell wide).
class Film {
 public:
  Film(const FilmArc& arc, double lengthOverDiameter, const ReynoldsGrid& grid,
       const JournalMotion& motion)
      : n_(grid.circumferential),
        m_(grid.axial),
        arc_(arc),
        motion_(motion),
        kappa_(1 / (lengthOverDiameter * lengthOverDiameter)),
        dt_(arc.span / n_),
        dz_(1.0 / m_) {
    // cos and sin at each node and its two faces, once: every axial cell of a column shares
    // them (the same angles as theta(i) +- dt / 2 give, so the same bits).
    trig_.reserve(std::size_t(n_) + 1);
    for (int i = 0; i <= n_; ++i) {
      const double ti = theta(i), te = ti + 0.5 * dt_, tw = ti - 0.5 * dt_;
      trig_.push_back({{{std::cos(ti), std::sin(ti)},
                        {std::cos(te), std::sin(te)},
                        {std::cos(tw), std::sin(tw)}}});
    }
  }

  int size() const { return (n_ - 1) * m_; }
  int index(int i, int j) const { return (i - 1) * m_ + j; }
  double theta(int i) const { return arc_.start + i * dt_; }
  /// Axial width of a cell (half at the mid-plane).
  double width(int j) const { return j == 0 ? 0.5 * dz_ : dz_; }
  /// Where on a column the film is read: its node, or its face towards larger or smaller theta.
  enum Place { node = 0, east = 1, west = 2 };
  double cosAt(int i, Place at) const { return trig_[std::size_t(i)][at][0]; }
  double sinAt(int i, Place at) const { return trig_[std::size_t(i)][at][1]; }
  double film(int i, Place at) const {
    return 1 + (arc_.a - motion_.displacement[0]) * cosAt(i, at) +
           (arc_.b - motion_.displacement[1]) * sinAt(i, at);
  }

  /// One node's links: conductances to its four neighbours (an index of -1 is a node held at
  /// P = 0), and how each conductance changes with the film there (d a / d H at the face).
  struct Links {
    int neighbour[4];
    double conductance[4];
    Place face[4];        ///< the face each conductance belongs to
    double slope[4];      ///< d conductance / d H at that face
  };

  Links links(int i, int j) const {
    const double w = width(j);
    const double he = film(i, east), hw = film(i, west), hi = film(i, node);
    const double axial = kappa_ * dt_ / dz_;
    Links l{};
    l.neighbour[0] = i + 1 < n_ ? index(i + 1, j) : -1;
    l.conductance[0] = he * he * he * w / dt_;
    l.slope[0] = 3 * he * he * w / dt_;
    l.face[0] = east;
    l.neighbour[1] = i - 1 >= 1 ? index(i - 1, j) : -1;
    l.conductance[1] = hw * hw * hw * w / dt_;
    l.slope[1] = 3 * hw * hw * w / dt_;
    l.face[1] = west;
    l.neighbour[2] = j + 1 < m_ ? index(i, j + 1) : -1;
    l.conductance[2] = hi * hi * hi * axial;
    l.slope[2] = 3 * hi * hi * axial;
    l.face[2] = node;
    // No flow through the mid-plane.
    l.neighbour[3] = j > 0 ? index(i, j - 1) : -1;
    l.conductance[3] = j > 0 ? hi * hi * hi * axial : 0;
    l.slope[3] = j > 0 ? 3 * hi * hi * axial : 0;
    l.face[3] = node;
    return l;
  }

  /// The film operator A (A P = f on pressurised nodes; symmetric, an M-matrix).
  FilmMatrix operatorMatrix() const {
    std::vector<Eigen::Triplet<double>> t;
    t.reserve(5 * size());
    forEachNode([&](int i, int j) {
      const int k = index(i, j);
      const Links l = links(i, j);
      double diagonal = 0;
      for (int d = 0; d < 4; ++d) {
        diagonal += l.conductance[d];
        if (l.neighbour[d] >= 0 && l.conductance[d] != 0)
          t.emplace_back(k, l.neighbour[d], -l.conductance[d]);
      }
      t.emplace_back(k, k, diagonal);
    });
    FilmMatrix a(size(), size());
    a.setFromTriplets(t.begin(), t.end());
    return a;
  }

  /// f: the wedge term -6 dH/dtheta and the squeeze term -12 dH/dtau over each cell, exact
  /// (H at the faces; dH/dtau = -(v1 cos + v2 sin) integrated in closed form).
  FilmVector wedge() const {
    FilmVector f(size());
    const double v1 = motion_.velocity[0], v2 = motion_.velocity[1];
    forEachNode([&](int i, int j) {
      const double squeeze = 12 * (v1 * (sinAt(i, east) - sinAt(i, west)) -
                                   v2 * (cosAt(i, east) - cosAt(i, west)));
      f[index(i, j)] = (-6 * (film(i, east) - film(i, west)) + squeeze) * width(j);
    });
    return f;
  }

  /// Derivatives of f and of A P for a journal displacement along axis `axis` (0: towards
  /// theta = 0, 1: towards theta = pi/2), dH = -(cos, sin)(theta) per unit of x / c, and of f
  /// for a journal velocity along it (dH/dtau = -(cos, sin) per unit of x' / (c Omega)).
  struct Perturbation {
    FilmVector displacement;  ///< d f / d x - (d A / d x) P
    FilmVector velocity;      ///< d f / d x'
  };

  Perturbation perturbation(int axis, const FilmVector& p) const {
    auto shape = [&](int i, Place at) { return axis == 0 ? -cosAt(i, at) : -sinAt(i, at); };
    // Exact cell integral of the shape: int cos = sin, int sin = -cos.
    auto integral = [&](int i, Place at) { return axis == 0 ? -sinAt(i, at) : cosAt(i, at); };
    Perturbation out{FilmVector::Zero(size()), FilmVector::Zero(size())};
    forEachNode([&](int i, int j) {
      const int k = index(i, j);
      double value = -6 * (shape(i, east) - shape(i, west)) * width(j);
      const Links l = links(i, j);
      for (int d = 0; d < 4; ++d) {
        const double other = l.neighbour[d] >= 0 ? p[l.neighbour[d]] : 0;
        value -= l.slope[d] * shape(i, l.face[d]) * (p[k] - other);
      }
      out.displacement[k] = value;
      out.velocity[k] = -12 * (integral(i, east) - integral(i, west)) * width(j);
    });
    return out;
  }

  /// -sum P (cos, sin) over the cells: Fbar.
  std::array<double, 2> force(const FilmVector& p) const {
    std::array<double, 2> f{0, 0};
    forEachNode([&](int i, int j) {
      const double area = dt_ * width(j) * p[index(i, j)];
      f[0] -= area * cosAt(i, node);
      f[1] -= area * sinAt(i, node);
    });
    return f;
  }

  template <class F>
  void forEachNode(F&& f) const {
    for (int i = 1; i < n_; ++i)
      for (int j = 0; j < m_; ++j) f(i, j);
  }

 private:
  int n_, m_;
  FilmArc arc_;
  JournalMotion motion_;
  double kappa_, dt_, dz_;
  std::vector<std::array<std::array<double, 2>, 3>> trig_;  ///< per column: Place -> cos, sin
};

/// The film operator on the pressurised nodes (others decoupled with a unit diagonal, their
/// right-hand side 0): symmetric positive definite.
FilmMatrix onPressurised(const FilmMatrix& a, const std::vector<char>& active) {
  FilmMatrix r = a;
  for (int col = 0; col < r.outerSize(); ++col)
    for (FilmMatrix::InnerIterator it(r, col); it; ++it)
      if (!active[it.row()] || !active[it.col()]) it.valueRef() = it.row() == it.col() ? 1.0 : 0.0;
  return r;
}

FilmVector maskedToPressurised(const FilmVector& v, const std::vector<char>& active) {
  FilmVector out = v;
  for (int k = 0; k < v.size(); ++k)
    if (!active[k]) out[k] = 0;
  return out;
}

}  // namespace

FilmSolution solveArcFilm(const FilmArc& arc, double lengthOverDiameter, const ReynoldsGrid& grid,
                          const JournalMotion& motion, bool withCoefficients,
                          std::vector<char>* cavity) {
  if (!(arc.span > 0 && arc.span <= 2 * kPiArc) || !(lengthOverDiameter > 0) ||
      grid.circumferential < 4 || grid.axial < 1)
    throw std::invalid_argument(
        "solveArcFilm: needs 0 < span <= 2 pi, L/D > 0 and a grid of at least 4 x 1");
  const Film film(arc, lengthOverDiameter, grid, motion);
  for (int i = 0; i <= grid.circumferential; ++i)
    if (!(film.film(i, Film::node) > 0))
      throw std::invalid_argument("solveArcFilm: the film closes on the arc");
  const FilmMatrix a = film.operatorMatrix();
  const FilmVector f = film.wedge();
  // Primal-dual active set: start from the converging half (f > 0), then keep the nodes
  // where P - w / a_kk > 0 (w = A P - f the complementary residual) until the set settles.
  std::vector<char> active(f.size());
  if (cavity && cavity->size() == active.size())
    active = *cavity;
  else
    for (int k = 0; k < f.size(); ++k) active[k] = f[k] > 0;
  // The nodes are numbered axial-fastest (index), so the operator is banded with half-width
  // m (the axial cells): factorising it in that order fills only the band, and skips the
  // fill-reducing ordering, which cost more than the factorisation on a pad's 24 x 8 grid.
  Eigen::SimplicialLDLT<FilmMatrix, Eigen::Lower, Eigen::NaturalOrdering<int>> solver;
  FilmVector p;
  FilmSolution out;
  for (int iteration = 1;; ++iteration) {
    const FilmMatrix r = onPressurised(a, active);
    if (iteration == 1) solver.analyzePattern(r);
    solver.factorize(r);
    if (solver.info() != Eigen::Success)
      throw std::runtime_error("solveFilm: the film operator did not factorise");
    p = solver.solve(maskedToPressurised(f, active));
    const FilmVector w = a * p - f;
    bool changed = false;
    for (int k = 0; k < f.size(); ++k) {
      const bool keep = p[k] - w[k] / a.coeff(k, k) > 0;
      changed |= keep != bool(active[k]);
      active[k] = keep;
    }
    out.activeSetIterations = iteration;
    if (!changed) break;
    if (iteration == 200)
      throw std::runtime_error("solveFilm: the cavity did not settle in 200 active-set steps");
  }
  for (int k = 0; k < p.size(); ++k)
    if (!active[k]) p[k] = 0;
  if (cavity) *cavity = active;
  const auto base = film.force(p);
  out.force[0] = base[0];
  out.force[1] = base[1];
  if (!withCoefficients) return out;
  for (int axis = 0; axis < 2; ++axis) {
    const Film::Perturbation d = film.perturbation(axis, p);
    const auto dk = film.force(solver.solve(maskedToPressurised(d.displacement, active)));
    const auto dc = film.force(solver.solve(maskedToPressurised(d.velocity, active)));
    for (int i = 0; i < 2; ++i) {
      out.stiffness[i][axis] = -dk[i];
      out.damping[i][axis] = -dc[i];
    }
  }
  return out;
}

}  // namespace beamrotor

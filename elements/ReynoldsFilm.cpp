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
        dz_(1.0 / m_) {}

  int size() const { return (n_ - 1) * m_; }
  int index(int i, int j) const { return (i - 1) * m_ + j; }
  double theta(int i) const { return arc_.start + i * dt_; }
  /// Axial width of a cell (half at the mid-plane).
  double width(int j) const { return j == 0 ? 0.5 * dz_ : dz_; }
  double film(double theta) const {
    return 1 + (arc_.a - motion_.displacement[0]) * std::cos(theta) +
           (arc_.b - motion_.displacement[1]) * std::sin(theta);
  }

  /// One node's links: conductances to its four neighbours (an index of -1 is a node held at
  /// P = 0), and how each conductance changes with the film there (d a / d H at the face).
  struct Links {
    int neighbour[4];
    double conductance[4];
    double faceTheta[4];  ///< theta of the face each conductance belongs to
    double slope[4];      ///< d conductance / d H at that face
  };

  Links links(int i, int j) const {
    const double w = width(j);
    const double te = theta(i) + 0.5 * dt_, tw = theta(i) - 0.5 * dt_, ti = theta(i);
    const double he = film(te), hw = film(tw), hi = film(ti);
    const double axial = kappa_ * dt_ / dz_;
    Links l{};
    l.neighbour[0] = i + 1 < n_ ? index(i + 1, j) : -1;
    l.conductance[0] = he * he * he * w / dt_;
    l.slope[0] = 3 * he * he * w / dt_;
    l.faceTheta[0] = te;
    l.neighbour[1] = i - 1 >= 1 ? index(i - 1, j) : -1;
    l.conductance[1] = hw * hw * hw * w / dt_;
    l.slope[1] = 3 * hw * hw * w / dt_;
    l.faceTheta[1] = tw;
    l.neighbour[2] = j + 1 < m_ ? index(i, j + 1) : -1;
    l.conductance[2] = hi * hi * hi * axial;
    l.slope[2] = 3 * hi * hi * axial;
    l.faceTheta[2] = ti;
    // No flow through the mid-plane.
    l.neighbour[3] = j > 0 ? index(i, j - 1) : -1;
    l.conductance[3] = j > 0 ? hi * hi * hi * axial : 0;
    l.slope[3] = j > 0 ? 3 * hi * hi * axial : 0;
    l.faceTheta[3] = ti;
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
      const double te = theta(i) + 0.5 * dt_, tw = theta(i) - 0.5 * dt_;
      const double squeeze =
          12 * (v1 * (std::sin(te) - std::sin(tw)) - v2 * (std::cos(te) - std::cos(tw)));
      f[index(i, j)] = (-6 * (film(te) - film(tw)) + squeeze) * width(j);
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
    auto shape = [axis](double t) { return axis == 0 ? -std::cos(t) : -std::sin(t); };
    // Exact cell integral of the shape: int cos = sin, int sin = -cos.
    auto integral = [axis](double t) { return axis == 0 ? -std::sin(t) : std::cos(t); };
    Perturbation out{FilmVector::Zero(size()), FilmVector::Zero(size())};
    forEachNode([&](int i, int j) {
      const int k = index(i, j);
      const double te = theta(i) + 0.5 * dt_, tw = theta(i) - 0.5 * dt_;
      double value = -6 * (shape(te) - shape(tw)) * width(j);
      const Links l = links(i, j);
      for (int d = 0; d < 4; ++d) {
        const double other = l.neighbour[d] >= 0 ? p[l.neighbour[d]] : 0;
        value -= l.slope[d] * shape(l.faceTheta[d]) * (p[k] - other);
      }
      out.displacement[k] = value;
      out.velocity[k] = -12 * (integral(te) - integral(tw)) * width(j);
    });
    return out;
  }

  /// -sum P (cos, sin) over the cells: Fbar.
  std::array<double, 2> force(const FilmVector& p) const {
    std::array<double, 2> f{0, 0};
    forEachNode([&](int i, int j) {
      const double area = dt_ * width(j) * p[index(i, j)];
      f[0] -= area * std::cos(theta(i));
      f[1] -= area * std::sin(theta(i));
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
    if (!(film.film(film.theta(i)) > 0))
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
  Eigen::SimplicialLDLT<FilmMatrix> solver;
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

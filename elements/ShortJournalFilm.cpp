#include "elements/ShortJournalFilm.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <numbers>
#include <sstream>
#include <stdexcept>

#include "fem/model/GaussLegendre.hpp"

namespace beamrotor {

ShortJournalFilm::ShortJournalFilm(const PlainJournal& journal) : PlainJournalFilm(journal) {
  if (!(journal.diameter > 0 && journal.length > 0 && journal.clearance > 0 &&
        journal.viscosity > 0))
    throw std::invalid_argument("a short-bearing film needs positive D, L, c and mu");
}

FilmForce ShortJournalFilm::at(const Eigen::Vector2d& position, const Eigen::Vector2d& velocity,
                               double speed) const {
  const double c = journal_.clearance;
  const double X = position[0] / c, Y = position[1] / c;
  const double eps = std::hypot(X, Y);
  requireInsideClearance(eps);
  const double Vy = velocity[0] / c, Vz = velocity[1] / c;
  // G = A sin(theta) + B cos(theta) = |G| cos(theta - theta0): negative on
  // (theta0 + pi/2, theta0 + 3 pi/2).
  const double A = 6 * speed * X - 12 * Vz, B = -6 * speed * Y - 12 * Vy;
  // A centred journal at rest has no film; its derivatives then depend on the direction of
  // the motion: the half-film below the +y axis is taken (any half would do).
  const double theta0 = (A == 0 && B == 0) ? 0.0 : std::atan2(A, B);
  static const GaussLegendre<64> rule;
  constexpr int n = GaussLegendre<64>::n;
  constexpr double kPi = std::numbers::pi, half = kPi / 2;
  // In three passes, each point's arithmetic as in one loop over the points: the angles' cos
  // and sin; each point's weighted terms (the same operations in the same order, point by
  // point, which the compiler may do two points at a time); their sums, in the points' order.
  std::array<double, n> co, si;
  for (int g = 0; g < n; ++g) {
    const double theta = theta0 + kPi + half * rule.x[g];
    co[g] = std::cos(theta);
    si[g] = std::sin(theta);
  }
  // wGh3 = w G / H^3; wd[k] = w d(G / H^3) / d(X, Y, Vy, Vz)[k], where
  // d(G / H^3) = dG / H^3 - 3 G / H^4 dH, dH/dX = -cos, dH/dY = -sin.
  std::array<double, n> wGh3;
  std::array<std::array<double, n>, 4> wd;
  for (int g = 0; g < n; ++g) {
    const double w = half * rule.w[g];
    const double H = 1 - X * co[g] - Y * si[g], G = A * si[g] + B * co[g];
    const double h3 = 1 / (H * H * H), h4 = h3 / H;
    wGh3[g] = w * G * h3;
    wd[0][g] = w * (6 * speed * si[g] * h3 + 3 * G * h4 * co[g]);
    wd[1][g] = w * (-6 * speed * co[g] * h3 + 3 * G * h4 * si[g]);
    wd[2][g] = w * (-12 * co[g] * h3);
    wd[3][g] = w * (-12 * si[g] * h3);
  }
  double F[2] = {0, 0}, dX[2][4] = {};  // dF_i / d(X, Y, Vy, Vz)
  for (int g = 0; g < n; ++g) {
    const double normal[2] = {co[g], si[g]};
    for (int i = 0; i < 2; ++i) {
      F[i] += wGh3[g] * normal[i];
      for (int j = 0; j < 4; ++j) dX[i][j] += wd[j][g] * normal[i];
    }
  }
  const double R = journal_.diameter / 2, L = journal_.length;
  const double scale = journal_.viscosity * R * L * L * L / (12 * c * c);
  FilmForce out;
  for (int i = 0; i < 2; ++i) {
    out.force[i] = scale * F[i];
    for (int j = 0; j < 2; ++j) {
      out.stiffness(i, j) = -scale * dX[i][j] / c;
      out.damping(i, j) = -scale * dX[i][j + 2] / c;
    }
  }
  return out;
}

PlainJournalFilm::Resting ShortJournalFilm::resting(double W, double speed) const {
  PlainJournal j = journal_;
  j.load = W;
  const double eps = eccentricityRatio(j, speed);
  return {eps, attitudeAngle(eps)};
}

}  // namespace beamrotor

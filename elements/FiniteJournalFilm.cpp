#include "elements/FiniteJournalFilm.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "elements/FiniteJournalBearing.hpp"

namespace beamrotor {

namespace {

/// Nearer the centre than this (/ c) the journal is taken this far out (see the header).
constexpr double kCentredFilm = 1e-9;
/// The spin (rad/s) a stopped journal's squeeze film is solved at (see the header).
constexpr double kSlowestFilmSpin = 1e-9;

Eigen::Matrix2d filmMatrix2(const double (&m)[2][2]) {
  Eigen::Matrix2d out;
  out << m[0][0], m[0][1], m[1][0], m[1][1];
  return out;
}

}  // namespace

FiniteJournalFilm::FiniteJournalFilm(const PlainJournal& journal, const ReynoldsGrid& grid)
    : PlainJournalFilm(journal), grid_(grid) {
  if (!(journal.diameter > 0 && journal.length > 0 && journal.clearance > 0 &&
        journal.viscosity > 0))
    throw std::invalid_argument("a finite journal film needs positive D, L, c and mu");
  if (grid.circumferential < 8 || grid.axial < 1)
    throw std::invalid_argument("a finite journal film needs a grid of at least 8 x 1 cells");
}

FilmForce FiniteJournalFilm::at(const Eigen::Vector2d& position, const Eigen::Vector2d& velocity,
                                double speed) const {
  const std::lock_guard<std::mutex> lock(mutex_);
  if (speed == memo_.speed && position == memo_.position && velocity == memo_.velocity)
    return memo_.film;
  memo_.film = solve(position, velocity, speed, memo_);
  memo_.position = position;
  memo_.velocity = velocity;
  memo_.speed = speed;
  return memo_.film;
}

FilmForce FiniteJournalFilm::solve(const Eigen::Vector2d& position,
                                   const Eigen::Vector2d& velocity, double speed,
                                   Memo& memo) const {
  const double c = journal_.clearance;
  const double eps = position.norm() / c;
  requireInsideClearance(eps);
  if (eps >= kCentredFilm) memo.direction = position / (eps * c);
  const double e = std::max(eps, kCentredFilm);
  // The film's axes: axis 1 towards the largest gap (opposite the journal), axis 2 a quarter
  // turn on in the sense of rotation.
  Eigen::Matrix2d R;
  R.col(0) = -memo.direction;
  R.col(1) = Eigen::Vector2d(memo.direction[1], -memo.direction[0]);
  const double spin = std::max(speed, kSlowestFilmSpin);
  const Eigen::Vector2d w = R.transpose() * velocity / (c * spin);
  FilmArc circle;
  circle.a = e;
  JournalMotion motion;
  motion.velocity[0] = w[0];
  motion.velocity[1] = w[1];
  const double ld = journal_.length / journal_.diameter;
  const FilmSolution s = solveArcFilm(circle, ld, grid_, motion, true, &memo.cavity);
  const Eigen::Vector2d f(s.force[0], s.force[1]);
  const Eigen::Matrix2d D = filmMatrix2(s.damping);
  Eigen::Matrix2d K = filmMatrix2(s.stiffness);
  // Across the line of centres the film turns with the journal (see the header).
  const auto quarter = [](const Eigen::Vector2d& x) { return Eigen::Vector2d(-x[1], x[0]); };
  K.col(1) = (quarter(f) + D * quarter(w)) / e;
  const double R3 = std::pow(journal_.diameter / 2, 3);
  const double scale = journal_.viscosity * spin * R3 * journal_.length / (c * c);
  FilmForce out;
  out.force = scale * (R * f);
  out.stiffness = (scale / c) * (R * K * R.transpose());
  out.damping = (scale / (c * spin)) * (R * D * R.transpose());
  return out;
}

PlainJournalFilm::Resting FiniteJournalFilm::resting(double W, double speed) const {
  PlainJournal j = journal_;
  j.load = W;
  const JournalOperatingPoint p = finiteJournalPoint(j, speed, grid_);
  return {p.eccentricity, p.attitude};
}

}  // namespace beamrotor

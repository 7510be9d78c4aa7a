#include "elements/TiltingPadJournalFilm.hpp"

#include <cmath>
#include <numbers>
#include <optional>
#include <stdexcept>
#include <string>

#include "fem/model/GaussLegendre.hpp"

namespace beamrotor {

namespace {

constexpr double kPiPadFilm = std::numbers::pi;

/// The placeholder damping on an idle massless pad's tilt, over mu R^5 L / c_p^3 (see the
/// header): small against any loaded pad's own (of order 1 and more), large against round-off.
constexpr double kIdlePadDamping = 1e-6;

/// int dphi / H over the pad's arc, H = 1 - a cos(phi) - s sin(phi) (a = m + rho): 64-point
/// Gauss-Legendre (H analytic and positive on the arc).
double couetteIntegral(double start, double span, double a, double s) {
  static const GaussLegendre<64> rule;
  double sum = 0;
  for (int g = 0; g < rule.n; ++g) {
    const double phi = start + span / 2 * (1 + rule.x[g]);
    sum += rule.w[g] / (1 - a * std::cos(phi) - s * std::sin(phi));
  }
  return sum * span / 2;
}

}  // namespace

TiltingPadJournalFilm::TiltingPadJournalFilm(const PlainJournal& journal,
                                             const TiltingPads& pads, const ReynoldsGrid& grid,
                                             double loadAngle)
    : journal_(journal), pads_(pads), grid_(grid), loadAngle_(loadAngle) {
  if (!(journal.diameter > 0 && journal.length > 0 && journal.clearance > 0 &&
        journal.viscosity > 0))
    throw std::invalid_argument("a tilting-pad film needs positive D, L, c and mu");
  if (pads.count < 1 || !(pads.arc > 0) || !(pads.count * pads.arc < 2 * kPiPadFilm) ||
      !(pads.pivotOffset > 0 && pads.pivotOffset < 1) ||
      !(pads.preload >= 0 && pads.preload < 1))
    throw std::invalid_argument("a tilting-pad film needs pads that fit, a pivot on each and "
                                "a preload in [0, 1)");
  padClearance_ = journal.clearance / (1 - pads.preload);
  for (int k = 0; k < pads.count; ++k)
    pivots_.push_back(loadAngle + kPiPadFilm + (pads.loadOnPad ? 0 : kPiPadFilm / pads.count) +
                      2 * kPiPadFilm * k / pads.count);
  films_.assign(pivots_.size(), PadFilm(pads, journal.length / journal.diameter, grid));
  states_.resize(pivots_.size());
}

Eigen::Vector2d TiltingPadJournalFilm::unit(double angle) const {
  return {std::cos(angle), std::sin(angle)};
}

FilmLoad TiltingPadJournalFilm::loadAt(const Eigen::VectorXd& state, const Eigen::VectorXd& rate,
                                       double speed) const {
  const std::lock_guard<std::mutex> lock(mutex_);
  return solve(state, rate, speed);
}

FilmLoad TiltingPadJournalFilm::solve(const Eigen::VectorXd& state, const Eigen::VectorXd& rate,
                                      double speed) const {
  const Eigen::Index n = Eigen::Index(pivots_.size()) + 2;
  if (state.size() != n || rate.size() != n)
    throw std::invalid_argument("a tilting-pad film's state is the journal's y, z and each "
                                "pad's tilt");
  if (speed == lastSpeed_ && state == lastState_ && rate == lastRate_) return lastLoad_;
  if (!(speed > 0))
    throw std::invalid_argument("a tilting-pad film carries its load only while the journal "
                                "spins (speed > 0)");
  const double cp = padClearance_, R = journal_.diameter / 2;
  const double scale = journal_.viscosity * speed * R * R * R * journal_.length / (cp * cp);
  const double stiffnessScale = scale / cp, dampingScale = scale / (cp * speed);
  FilmLoad out{Eigen::VectorXd::Zero(n), Eigen::MatrixXd::Zero(n, n), Eigen::MatrixXd::Zero(n, n)};
  for (std::size_t k = 0; k < pivots_.size(); ++k) {
    const Eigen::Index tilt = Eigen::Index(k) + 2;
    const Eigen::Vector2d e = unit(pivots_[k]), t = unit(pivots_[k] + kPiPadFilm / 2);
    // B = [e t; 0 -R] over (y, z, delta_k): w = B^T x.
    Eigen::Matrix<double, 3, 2> B;
    B << e[0], t[0], e[1], t[1], 0, -R;
    const Eigen::Vector3d x(state[0], state[1], state[tilt]), v(rate[0], rate[1], rate[tilt]);
    const Eigen::Vector2d w = B.transpose() * x / cp, wRate = B.transpose() * v / (cp * speed);
    PadState& pad = states_[k];
    pad = PadState{w[0], w[1], 0, 0};
    PadFilm& film = films_[k];
    if (!(film.thinnest(w[0], w[1]) > 0))
      throw JournalLeftClearance("pad " + std::to_string(k + 1) +
                                 ": its film closes (the journal at " +
                                 std::to_string(state.head<2>().norm() / journal_.clearance) +
                                 " of the bearing clearance touches the pad)");
    const double rates[2] = {wRate[0], wRate[1]};
    const FilmSolution f = film.solveMoving(w[0], w[1], rates);
    const Eigen::Vector2d force(f.force[0], f.force[1]);
    Eigen::Matrix2d K, C;
    K << f.stiffness[0][0], f.stiffness[0][1], f.stiffness[1][0], f.stiffness[1][1];
    C << f.damping[0][0], f.damping[0][1], f.damping[1][0], f.damping[1][1];
    pad.forceE = scale * force[0];
    pad.forceT = scale * force[1];
    const Eigen::Vector3d generalised = scale * B * force;
    const Eigen::Matrix3d stiffness = stiffnessScale * B * K * B.transpose();
    Eigen::Matrix3d damping = dampingScale * B * C * B.transpose();
    // An idle pad (its film diverges everywhere): the placeholder on its tilt (see the header).
    if (force.isZero(0) && K.isZero(0) && C.isZero(0))
      damping(2, 2) = kIdlePadDamping * dampingScale * R * R;
    const Eigen::Index at[3] = {0, 1, tilt};
    for (int r = 0; r < 3; ++r) {
      out.force[at[r]] += generalised[r];
      for (int c = 0; c < 3; ++c) {
        out.stiffness(at[r], at[c]) += stiffness(r, c);
        out.damping(at[r], at[c]) += damping(r, c);
      }
    }
  }
  lastState_ = state;
  lastRate_ = rate;
  lastSpeed_ = speed;
  lastLoad_ = out;
  return out;
}

Eigen::VectorXd TiltingPadJournalFilm::restState(const Eigen::Vector2d& load, double speed) const {
  const std::lock_guard<std::mutex> lock(mutex_);
  const double cp = padClearance_, R = journal_.diameter / 2;
  const double W = load.norm();
  if (W > 0 && (load + W * unit(loadAngle_)).norm() > 1e-9 * W)
    throw std::invalid_argument("a tilting-pad film carries its load along the bearing's load "
                                "line (-x_b)");
  Eigen::VectorXd out = Eigen::VectorXd::Zero(Eigen::Index(pivots_.size()) + 2);
  std::vector<std::optional<double>> tilts(pivots_.size());  // s of each loaded pad
  if (W > 0) {
    PlainJournal j = journal_;
    j.load = W;
    const TiltingPadPoint p = tiltingPadPoint(j, pads_, speed, grid_);
    out.head<2>() = p.eccentricity * journal_.clearance *
                    unit(p.attitude + kPiPadFilm + loadAngle_);
    for (std::size_t k = 0; k < pivots_.size(); ++k)
      if (p.pads[k].force != 0)
        tilts[k] = (out.head<2>().dot(unit(pivots_[k] + kPiPadFilm / 2)) - p.pads[k].tilt * R) / cp;
  } else {
    for (std::size_t k = 0; k < pivots_.size(); ++k) tilts[k] = films_[k].equilibriumTilt(0);
  }
  for (std::size_t k = 0; k < pivots_.size(); ++k) {
    const Eigen::Vector2d u = out.head<2>() / cp;
    const double rho = u.dot(unit(pivots_[k]));
    // An unloaded pad: where its film just stops converging (see the header).
    const double s = tilts[k] ? *tilts[k]
                              : (pads_.preload + rho) *
                                    std::tan((1 - pads_.pivotOffset) * pads_.arc);
    out[Eigen::Index(k) + 2] = (u.dot(unit(pivots_[k] + kPiPadFilm / 2)) - s) * cp / R;
  }
  return out;
}

double TiltingPadJournalFilm::dragTorqueAt(const Eigen::VectorXd& state,
                                           const Eigen::VectorXd& force, double speed) const {
  const std::lock_guard<std::mutex> lock(mutex_);
  if (!(speed > 0)) return 0;
  const bool pressure = !force.isZero(0);
  if (state != lastState_ || speed != lastSpeed_)
    solve(state, Eigen::VectorXd::Zero(state.size()), speed);
  const double cp = padClearance_, R = journal_.diameter / 2;
  const double couette = journal_.viscosity * speed * R * R * R * journal_.length / cp;
  const double start = -pads_.pivotOffset * pads_.arc;
  double torque = 0;
  for (const PadState& p : states_) {
    const double a = pads_.preload + p.rho;
    torque += couette * couetteIntegral(start, pads_.arc, a, p.s);
    // x_k x F_k / 2 in pad axes: x_k = c_p (a, s), F_k = (F_e, F_t).
    if (pressure) torque += cp * (a * p.forceT - p.s * p.forceE) / 2;
  }
  return torque;
}

}  // namespace beamrotor

#include "elements/TiltingPadJournalFilm.hpp"

#include <cmath>
#include <numbers>
#include <stdexcept>
#include <string>

#include "fem/model/GaussLegendre.hpp"

namespace beamrotor {

namespace {

constexpr double kPiPadFilm = std::numbers::pi;

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
    : journal_(journal), pads_(pads) {
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

FilmForce TiltingPadJournalFilm::at(const Eigen::Vector2d& position,
                                    const Eigen::Vector2d& velocity, double speed) const {
  const std::lock_guard<std::mutex> lock(mutex_);
  return solve(position, velocity, speed);
}

FilmForce TiltingPadJournalFilm::solve(const Eigen::Vector2d& position,
                                       const Eigen::Vector2d& velocity, double speed) const {
  if (speed == lastSpeed_ && position == lastPosition_ && velocity == lastVelocity_)
    return lastForce_;
  if (!(speed > 0))
    throw std::invalid_argument("a tilting-pad film carries its load only while the journal "
                                "spins (speed > 0)");
  const double cp = padClearance_, R = journal_.diameter / 2;
  const double scale = journal_.viscosity * speed * R * R * R * journal_.length / (cp * cp);
  FilmForce out;
  for (std::size_t k = 0; k < pivots_.size(); ++k) {
    const Eigen::Vector2d e = unit(pivots_[k]);
    PadState& state = states_[k];
    state = PadState{};
    state.rho = position.dot(e) / cp;
    if (!(pads_.preload + state.rho < 1)) requireInsideClearance(1);
    PadFilm& film = films_[k];
    const double squeeze = velocity.dot(e) / (cp * speed);
    // A pad the journal has left carries nothing (PadFilm's equilibriumTilt concludes so after
    // scanning its tilts), its squeeze included.
    if (pads_.preload + state.rho <= 0) {
      continue;
    }
    film.setSqueeze(squeeze);
    try {
      state.s = film.equilibriumTilt(state.rho);
      if (!state.s) continue;  // the journal has left the pad
      const FilmSolution f = film.solve(state.rho, *state.s, true);
      const double kr = f.stiffness[0][0] - f.stiffness[0][1] * f.stiffness[1][0] / f.stiffness[1][1];
      const double cr = f.damping[0][0] - f.stiffness[0][1] * f.damping[1][0] / f.stiffness[1][1];
      state.force = scale * f.force[0];
      out.force += state.force * e;
      out.stiffness += (scale / cp * kr) * e * e.transpose();
      out.damping += (scale / (cp * speed) * cr) * e * e.transpose();
    } catch (const std::invalid_argument& error) {
      // The film closes on the pad (the journal touches it) or cannot be balanced on its pivot.
      throw JournalLeftClearance("pad " + std::to_string(k + 1) + ": " + error.what() +
                                 " (the journal at " + std::to_string(position.norm() /
                                                                      journal_.clearance) +
                                 " of the bearing clearance)");
    }
  }
  lastPosition_ = position;
  lastVelocity_ = velocity;
  lastSpeed_ = speed;
  lastForce_ = out;
  return out;
}

Eigen::Vector2d TiltingPadJournalFilm::equilibrium(const Eigen::Vector2d& load,
                                                   double speed) const {
  const std::lock_guard<std::mutex> lock(mutex_);
  const double cp = padClearance_, R = journal_.diameter / 2;
  const double scale = journal_.viscosity * speed * R * R * R * journal_.length / (cp * cp);
  const double tolerance = 1e-12 * (load.norm() > 0 ? load.norm() : scale);
  // Films thinner than 1 % of c_b at a pivot are beyond any surface finish (as the bearing's
  // own equilibrium): a Newton step is shortened to keep half the room left there.
  const double thinnest = 0.01 * (1 - pads_.preload);
  Eigen::Vector2d u = Eigen::Vector2d::Zero();  // over c_p
  for (int iteration = 0;; ++iteration) {
    const FilmForce f = solve(cp * u, Eigen::Vector2d::Zero(), speed);
    const Eigen::Vector2d residual = f.force + load;
    if (residual.norm() <= tolerance) return cp * u;
    if (iteration == 100)
      throw std::invalid_argument("the tilting pads found no equilibrium in 100 Newton steps");
    const Eigen::Vector2d step = f.stiffness.fullPivLu().solve(residual) / cp;
    double shorten = 1;
    for (double pivot : pivots_) {
      const double room = 1 - pads_.preload - thinnest - u.dot(unit(pivot));
      const double advance = step.dot(unit(pivot));
      if (advance > 0.5 * room) shorten = std::min(shorten, 0.5 * room / advance);
    }
    if (!(shorten > 1e-6))
      throw std::invalid_argument("the load needs a film thinner than 1 % of the clearance at a "
                                  "pivot (the journal touches a pad)");
    u += shorten * step;
  }
}

double TiltingPadJournalFilm::dragTorque(const Eigen::Vector2d& position,
                                         const Eigen::Vector2d& force, double speed) const {
  const std::lock_guard<std::mutex> lock(mutex_);
  if (!(speed > 0)) return 0;
  const bool pressure = force.squaredNorm() > 0;
  if (position != lastPosition_ || speed != lastSpeed_)
    solve(position, Eigen::Vector2d::Zero(), speed);
  const double cp = padClearance_, R = journal_.diameter / 2;
  const double couette = journal_.viscosity * speed * R * R * R * journal_.length / cp;
  const double start = -pads_.pivotOffset * pads_.arc;
  double torque = 0;
  for (const PadState& p : states_) {
    const double a = pads_.preload + p.rho, s = p.s.value_or(0.0);
    torque += couette * couetteIntegral(start, pads_.arc, a, s);
    // x_k x F_k / 2 in pad axes: x_k = c_p (a, s), F_k = (force, 0).
    if (pressure && p.s) torque += -cp * s * p.force / 2;
  }
  return torque;
}

}  // namespace beamrotor

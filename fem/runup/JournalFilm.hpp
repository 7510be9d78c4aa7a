// A journal bearing's oil film as a nonlinear force for the run-up: the force on the journal at
// its instantaneous position and velocity in the bearing and at the instantaneous spin speed,
// with the exact derivatives the Newton iterations of an implicit step need. The film theories
// live in elements/ (elements/ShortJournalFilm.hpp: Ocvirk's short bearing); fem/runup/RunUp
// steps a rotor with them in place of the bearings' linearised coefficients.
#pragma once

#include <Eigen/Dense>
#include <memory>
#include <sstream>
#include <stdexcept>
#include <string>

namespace beamrotor {

/// The film force on the journal and its derivatives, global (y, z).
struct FilmForce {
  Eigen::Vector2d force = Eigen::Vector2d::Zero();      ///< N
  Eigen::Matrix2d stiffness = Eigen::Matrix2d::Zero();  ///< -dF/d(position), N/m
  Eigen::Matrix2d damping = Eigen::Matrix2d::Zero();    ///< -dF/d(velocity), N s/m
};

/// Thrown when the journal reaches the bearing's wall (eccentricity ratio >= 1): the film
/// theory has no answer there.
struct JournalLeftClearance : std::runtime_error {
  using std::runtime_error::runtime_error;
};

/// Throws JournalLeftClearance, naming the eccentricity ratio, unless eps < 1.
inline void requireInsideClearance(double eps) {
  if (eps < 1) return;
  std::ostringstream msg;
  msg << "the journal left the bearing's clearance (eccentricity ratio " << eps
      << " >= 1): the film cannot carry the motion; lower the unbalance or the speed, or "
         "check c";
  throw JournalLeftClearance(msg.str());
}

class JournalFilm {
 public:
  virtual ~JournalFilm() = default;
  /// The force at journal position `position` (m, from the bearing's centre) moving at
  /// `velocity` (m/s), spin speed `speed` (rad/s, > 0). Throws JournalLeftClearance at an
  /// eccentricity ratio >= 1.
  virtual FilmForce at(const Eigen::Vector2d& position, const Eigen::Vector2d& velocity,
                       double speed) const = 0;
  /// Where the journal rests carrying `load` (N, global (y, z): the force the shaft puts on
  /// the film) at `speed`, by the film's own equilibrium solution.
  virtual Eigen::Vector2d equilibrium(const Eigen::Vector2d& load, double speed) const = 0;
  /// The film's viscous torque resisting the journal's spin (N m, > 0 for speed > 0) with the
  /// journal at `position` (m, from the bearing's centre) while the film pushes on it with
  /// `force` (N, the force at()'s answer).
  virtual double dragTorque(const Eigen::Vector2d& position, const Eigen::Vector2d& force,
                            double speed) const = 0;
  /// Radial clearance c (m).
  virtual double clearance() const = 0;
};

/// A bearing whose film force replaces its linearised coefficients in a run-up.
struct NonlinearJournal {
  std::string name;
  int element = -1;  ///< the model's bearing element (its coefficients are taken out)
  int node = -1;     ///< the journal's node (uy, uz free)
  std::shared_ptr<const JournalFilm> film;
  /// The bearing's static load (N, global (y, z)), the force the shaft puts on the film: the
  /// journal starts where the film carries it at the start speed (u = 0 there), and unless
  /// the run-up's gravity carries it, it acts on the journal as a constant force (the load the
  /// linear coefficients are taken at).
  Eigen::Vector2d load = Eigen::Vector2d::Zero();
};

}  // namespace beamrotor

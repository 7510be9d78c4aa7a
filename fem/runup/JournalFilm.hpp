// A journal bearing's oil film as a nonlinear force for the run-up: the force on the journal at
// its instantaneous position and velocity in the bearing and at the instantaneous spin speed,
// with the exact derivatives the Newton iterations of an implicit step need. The film theories
// live in elements/ (elements/ShortJournalFilm.hpp: Ocvirk's short bearing); fem/runup/RunUp
// steps a rotor with them in place of the bearings' linearised coefficients.
//
// A film may own degrees of freedom beyond the journal's (BearingFilm::ownDofs: a tilting pad's
// tilt, elements/TiltingPadJournalFilm.hpp): its state is then the journal's (y, z) and its own
// dofs, and it returns the generalised forces on all of them with their (2 + n) x (2 + n)
// derivatives. A plain journal owns none (JournalFilm: force and 2 x 2 derivatives).
#pragma once

#include <Eigen/Dense>
#include <memory>
#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>

#include "fem/model/Dof.hpp"

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

/// The generalised film forces on (y, z, own dofs) and their derivatives.
struct FilmLoad {
  Eigen::VectorXd force;      ///< N on y, z; the own dofs' generalised forces (N m on a tilt)
  Eigen::MatrixXd stiffness;  ///< -d force / d state
  Eigen::MatrixXd damping;    ///< -d force / d rate
};

/// A film over the journal's (y, z) and `ownDofs()` dofs of its own.
class BearingFilm {
 public:
  virtual ~BearingFilm() = default;
  /// Dofs of the film's own beyond the journal's (y, z).
  virtual int ownDofs() const = 0;
  /// The forces at `state` (journal y, z in m from the bearing's centre, then the own dofs)
  /// moving at `rate`, spin `speed` (rad/s, > 0). Throws JournalLeftClearance when the journal
  /// reaches the bearing's wall.
  virtual FilmLoad loadAt(const Eigen::VectorXd& state, const Eigen::VectorXd& rate,
                          double speed) const = 0;
  /// The resting state carrying `load` (N, global (y, z), the force the shaft puts on the
  /// film) at `speed`: the journal's place and the own dofs where their forces vanish.
  virtual Eigen::VectorXd restState(const Eigen::Vector2d& load, double speed) const = 0;
  /// The film's viscous torque on the spin at `state` while it pushes with `force` (loadAt's
  /// answer there; a zero vector: the Couette part alone, its slope in the speed).
  virtual double dragTorqueAt(const Eigen::VectorXd& state, const Eigen::VectorXd& force,
                              double speed) const = 0;
  /// Radial clearance c (m).
  virtual double clearance() const = 0;
  /// Own dof k's name in the outputs (a column's suffix, e.g. "pad1_tilt").
  virtual std::string ownDofName(int k) const { return "dof" + std::to_string(k + 1); }
};

/// A film over the journal's (y, z) alone: a plain journal bearing.
class JournalFilm : public BearingFilm {
 public:
  int ownDofs() const final { return 0; }
  FilmLoad loadAt(const Eigen::VectorXd& state, const Eigen::VectorXd& rate,
                  double speed) const final {
    const FilmForce f = at(state.head<2>(), rate.head<2>(), speed);
    return {f.force, f.stiffness, f.damping};
  }
  Eigen::VectorXd restState(const Eigen::Vector2d& load, double speed) const final {
    return equilibrium(load, speed);
  }
  double dragTorqueAt(const Eigen::VectorXd& state, const Eigen::VectorXd& force,
                      double speed) const final {
    return dragTorque(state.head<2>(), force.head<2>(), speed);
  }
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
};

/// A bearing whose film force replaces its linearised coefficients in a run-up.
struct NonlinearJournal {
  std::string name;
  int element = -1;  ///< the model's bearing element (its coefficients are taken out)
  int node = -1;     ///< the journal's node (uy, uz free)
  std::shared_ptr<const BearingFilm> film;
  /// A film with dofs of its own: per own dof, the model's element holding its linear
  /// coefficients between the journal's uy, uz and that dof (taken out as `element`'s are;
  /// `element` is then -1), and the dof.
  std::vector<int> ownElements;
  std::vector<NodeDof> ownDofs;
  /// The bearing's static load (N, global (y, z)), the force the shaft puts on the film: the
  /// journal starts where the film carries it at the start speed (u = 0 there), and unless
  /// the run-up's gravity carries it, it acts on the journal as a constant force (the load the
  /// linear coefficients are taken at).
  Eigen::Vector2d load = Eigen::Vector2d::Zero();
};

}  // namespace beamrotor

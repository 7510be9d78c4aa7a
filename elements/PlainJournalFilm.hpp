// What a plain journal bearing's nonlinear film does the same whatever its film theory (short,
// elements/ShortJournalFilm.hpp, or finite, elements/FiniteJournalFilm.hpp): the clearance,
// the drag on the spin (journalDragTorque) and the resting place carrying a load, the film's
// own eccentricity and attitude for that load turned to the load's line.
#pragma once

#include <cmath>

#include "elements/PlainJournalBearing.hpp"
#include "fem/runup/JournalFilm.hpp"

namespace beamrotor {

class PlainJournalFilm : public JournalFilm {
 public:
  Eigen::Vector2d equilibrium(const Eigen::Vector2d& load, double speed) const final {
    const double W = load.norm();
    if (W == 0) return Eigen::Vector2d::Zero();  // an unloaded journal runs centred
    const Resting r = resting(W, speed);
    const double angle = std::atan2(load[1], load[0]) + r.attitude;
    return r.eccentricity * journal_.clearance * Eigen::Vector2d(std::cos(angle), std::sin(angle));
  }
  /// The film's torque resisting the journal's spin (N m): journalDragTorque.
  double dragTorque(const Eigen::Vector2d& position, const Eigen::Vector2d& force,
                    double speed) const final {
    return journalDragTorque(journal_, position, force, speed);
  }
  double clearance() const final { return journal_.clearance; }

 protected:
  /// The journal's geometry and oil (its `load` is not used: the load comes with each call).
  explicit PlainJournalFilm(const PlainJournal& journal) : journal_(journal) {}

  /// Where the film's theory rests the journal under a load: eccentricity ratio, and attitude
  /// (rad) from the load's line in the sense of rotation.
  struct Resting {
    double eccentricity = 0, attitude = 0;
  };
  /// The resting place carrying load `W` (N, > 0) at `speed` (rad/s).
  virtual Resting resting(double W, double speed) const = 0;

  PlainJournal journal_;
};

}  // namespace beamrotor

// The run-up options the film tests share: a Jeffcott rotor (a disk on a shaft spring to a
// journal node) whose bearing element holds a film's linear coefficients, run at a time step
// with an unbalance on the disk, either on those coefficients or on the film itself.
#pragma once

#include <memory>

#include "fem/runup/JournalFilm.hpp"
#include "fem/runup/RunUp.hpp"

namespace beamrotor::test {

/// Steady start, the disk's and the journal's histories; unbalance `me` on the disk (none
/// when 0). With `film`, the bearing element `bearing` acts by it instead, carrying `load`
/// (N, global (y, z)).
inline RunUpOptions filmRunUpOptions(int disk, int journal, int bearing, double dt, double me,
                                     std::shared_ptr<const JournalFilm> film,
                                     const Eigen::Vector2d& load) {
  RunUpOptions o;
  o.timeStep = dt;
  o.start = RunUpStart::steady;
  if (me > 0) {
    Unbalance u;
    u.node = disk;
    u.me = me;
    o.unbalance = {u};
  }
  o.nodes = {disk, journal};
  if (film) {
    NonlinearJournal j;
    j.name = "journal";
    j.element = bearing;
    j.node = journal;
    j.film = std::move(film);
    j.load = load;
    o.journals = {j};
  }
  return o;
}

}  // namespace beamrotor::test

// What the film run-up tests share: the options of a Jeffcott rotor (a disk on a shaft spring
// to a journal node) whose bearing element holds a film's linear coefficients, run at a time
// step with an unbalance on the disk, either on those coefficients or on the film itself; and
// the orbit measures they compare runs by.
#pragma once

#include <algorithm>
#include <cmath>
#include <cstddef>
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

/// The largest distance between two runs' recorded positions of their first history (the disk).
inline double largestDiskDifference(const RunUpResult& a, const RunUpResult& b) {
  double d = 0;
  for (std::size_t i = 0; i < a.times.size(); ++i)
    d = std::max(d, std::hypot(a.histories[0].uy[i] - b.histories[0].uy[i],
                               a.histories[0].uz[i] - b.histories[0].uz[i]));
  return d;
}

/// The largest radius of an orbit from sample `from` on.
inline double largestOrbitRadius(const RunUpHistory& h, std::size_t from = 0) {
  double r = 0;
  for (std::size_t i = from; i < h.uy.size(); ++i) r = std::max(r, std::hypot(h.uy[i], h.uz[i]));
  return r;
}

}  // namespace beamrotor::test

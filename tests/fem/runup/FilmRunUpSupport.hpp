// What the film run-up tests share: a Jeffcott rotor (a disk on a shaft spring to a journal
// node) whose bearing element holds a film's linear coefficients, and its options, run at a
// time step with an unbalance on the disk, either on those coefficients or on the film itself;
// and the orbit measures they compare runs by.
#pragma once

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <memory>

#include "elements/Bearing.hpp"
#include "elements/PointInertia.hpp"
#include "elements/Spring.hpp"
#include "fem/model/Model.hpp"
#include "fem/runup/JournalFilm.hpp"
#include "fem/runup/RunUp.hpp"

namespace beamrotor::test {

/// The rotor's nodes and its bearing element.
struct FilmJeffcott {
  int disk = -1, journal = -1, bearing = -1;
};

/// Into `model`: a disk (20 kg) on a shaft spring (1e6 N/m) to a journal node (0.5 kg, 0.1 m
/// along x) whose Bearing element holds `coefficients`; with `diskDamping` > 0 (N s/m) a damper
/// from the disk to the ground as well.
inline FilmJeffcott buildFilmJeffcott(Model& model, const BearingCoefficients& coefficients,
                                      double diskDamping = 0) {
  FilmJeffcott r;
  r.disk = model.addNode({0, 0, 0});
  r.journal = model.addNode({0.1, 0, 0});
  model.add<PointInertia>(r.disk, DofSet{Dof::uy, Dof::uz}, 20.0);
  model.add<PointInertia>(r.journal, DofSet{Dof::uy, Dof::uz}, 0.5);
  for (Dof d : {Dof::uy, Dof::uz}) {
    model.add<Spring>(NodeDof{r.disk, d}, NodeDof{r.journal, d}, 1e6);
    if (diskDamping > 0) model.add<Spring>(NodeDof{r.disk, d}, 0.0, diskDamping);
  }
  model.add<Bearing>(r.journal, coefficients);
  r.bearing = int(model.elements().size()) - 1;
  return r;
}

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

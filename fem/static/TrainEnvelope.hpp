// The envelope of a quantity under a train of point loads crossing a path, from the quantity's
// influence line (InfluenceLines.hpp): exact, not sampled. With the train's first load at
// distance x along the path, the effect is the sum of each load times the influence line where
// that load stands; between consecutive breaks (x where some load crosses a break of the
// influence line) every term is one piece of the line read along a shifted variable, so the
// sum is a cubic whose extremes lie at the ends or where its slope vanishes.
#pragma once

#include <vector>

#include "fem/static/InfluenceLines.hpp"

namespace beamrotor {

/// One load of a train: its value along the influence line's unit direction (N) and its
/// distance behind the first load (m, 0 for the first).
struct TrainLoad {
  double force = 0;
  double offset = 0;
};

/// An extreme of the effect and the first load's position that gives it (m along the path).
/// Where the effect jumps (a shear force under a load) the value is the limit on the side
/// that gives it.
struct TrainExtreme {
  double value = 0;
  double lead = 0;
};

struct TrainEnvelope {
  TrainExtreme max, min;
};

/// The effect with the first load at `lead` (m along the path); a load off the path (before
/// its start or past its end) carries nothing.
double trainEffect(const InfluenceLine& line, const std::vector<TrainLoad>& train, double lead);

/// The largest and smallest effect while the train crosses the whole path: the first load from
/// the path's start until the last leaves it at the end.
TrainEnvelope trainEnvelope(const InfluenceLine& line, const std::vector<TrainLoad>& train);

/// The nodal displacements (exact at the nodes) under the train alone with its first load at
/// `lead`: each load on the path times its shares of the unit loads' solutions.
NodalField trainDisplacement(const PathUnitLoads& units, const std::vector<TrainLoad>& train,
                             double lead);

}  // namespace beamrotor

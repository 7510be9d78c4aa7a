// Builds a drive train in torsion: shaft lines of beams carrying the twist rx alone, disks
// (polar inertia) at named stations, flexible couplings between stations, and gear meshes
// joining two shafts by a speed ratio (elements/GearMesh.hpp). The shafts are laid end to
// end along x, each after the last with a gap, so that a chart of the twist along x shows
// the whole train; the twist of each shaft is its own (not referred to another's speed).
#pragma once

#include <string>
#include <vector>

#include "meshes/LineBuilder.hpp"

namespace beamrotor {

/// One shaft line: its segments from its start and named stations on it. Its start and end
/// are stations "start" and "end" too.
struct TrainShaft {
  std::string name;
  std::vector<Segment> segments;
  std::vector<NamedPoint> stations;  ///< distance from the shaft's start (m)
};

/// A station of the train: shaft and station name ("start", "end" or one of its stations).
struct TrainStation {
  std::string shaft, station;
  std::string name() const { return shaft + "." + station; }
};

struct TrainDisk {
  TrainStation at;
  double Jp = 0;  ///< kg m^2
};

/// A coupling (ratio 1, its twist from - to) or a gear mesh (ratio = w_from / w_to).
struct TrainJoint {
  std::string name;
  TrainStation from, to;
  double stiffness = 0;  ///< N m/rad (a mesh's: referred to the `from` shaft)
  double damping = 0;    ///< N m s/rad
  double ratio = 1;
};

struct TrainSpec {
  std::vector<TrainShaft> shafts;
  std::vector<TrainDisk> disks;
  std::vector<TrainJoint> couplings, gears;
};

/// What the builder made: each shaft's line and the element of each coupling and gear (indices
/// into the model's elements, in the spec's order). Every station's node is named
/// "SHAFT.STATION"; couplings and gears are named elements.
struct TrainMesh {
  std::vector<Line> shafts;
  std::vector<int> couplings, gears;
};

/// Adds the train to `model` (whose dofs are only rx). Throws std::invalid_argument for a
/// station no shaft has or a bad value.
TrainMesh buildTrain(Model& model, const TrainSpec& spec);

/// Each shaft's speed over the first shaft's, through the gears (couplings keep the speed).
/// Throws std::invalid_argument naming a shaft no joint reaches from the first, or a loop of
/// joints whose ratios disagree.
std::vector<double> shaftSpeedRatios(const TrainSpec& spec);

}  // namespace beamrotor

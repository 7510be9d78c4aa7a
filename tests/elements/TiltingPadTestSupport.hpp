// The tilting-pad bearing the tests share: a 100 mm journal, L/D 0.5, on four 80 deg pads
// with preload 0.3, the load between two of them (the shipped compressor's pad geometry).
#pragma once

#include <array>
#include <memory>
#include <numbers>
#include <vector>

#include "elements/PointInertia.hpp"
#include "elements/TiltingPadBearing.hpp"
#include "elements/TiltingPadFilm.hpp"
#include "fem/model/Model.hpp"
#include "meshes/LineBuilder.hpp"

namespace beamrotor::test {

inline PlainJournal tiltingPadTestJournal() {
  PlainJournal j;
  j.diameter = 0.1;
  j.length = 0.05;
  j.clearance = 100e-6;
  j.viscosity = 0.02;
  j.load = 5000;
  return j;
}

inline TiltingPads fourPadsBetween() {
  TiltingPads p;
  p.count = 4;
  p.arc = 80 * std::numbers::pi / 180;
  p.pivotOffset = 0.5;
  p.preload = 0.3;
  p.loadOnPad = false;
  return p;
}

/// The test bearing's operating point at `speed` (rad/s), 24 x 8 cells a pad.
inline TiltingPadPoint padPoint(double speed,
                                const TiltingPads& pads = fourPadsBetween()) {
  return tiltingPadPoint(tiltingPadTestJournal(), pads, speed, {24, 8});
}

/// A steel shaft (1 m, 100 mm) with a 300 kg disk at mid-span; the bearings are added by the
/// caller at the returned end nodes.
inline std::array<int, 2> buildShaft(Model& model) {
  auto sec = std::make_shared<Section>(
      Section::circle("shaft", Material::fromEnu("steel", 2.1e11, 0.3, 7850), 0.1));
  LineSpec spec;
  spec.dofs = DofSet::lateral();
  spec.segments.push_back({1.0, sec, 8, 0, {}});
  spec.points = {{"left", 0}, {"disk", 0.5}, {"right", 1.0}};
  buildLine(model, spec);
  model.add<PointInertia>(model.node("disk"), DofSet::lateral(), 300.0, 6.0, 3.0,
                          Eigen::Vector3d::UnitX());
  return {model.node("left"), model.node("right")};
}

/// `point`'s pads at each of `journals` with every loaded pad's tilt a dof of its own node
/// (elements/TiltingPadFilm.hpp), each pad's polar inertia `inertia` (kg m^2); the pad films.
inline int addPadTilts(Model& model, std::array<int, 2> journals, const TiltingPadPoint& point,
                       double inertia) {
  auto points = std::make_shared<const std::vector<TiltingPadPoint>>(1, point);
  int films = 0;
  for (int journal : journals)
    for (int pad = 0; pad < int(point.pads.size()); ++pad) {
      if (!padEverLoaded(*points, pad)) continue;
      const int node = model.addNode(model.nodes()[journal]);
      model.add<TiltingPadFilm>(journal, node, points, pad, 0.0, inertia);
      ++films;
    }
  return films;
}

}  // namespace beamrotor::test

// Builds a straight line of beam elements from segments (length, section, element count or
// target size), keeping every named point (supports, steps, load points) on a node.
#pragma once

#include <memory>
#include <string>
#include <vector>

#include "elements/Beam.hpp"
#include "fem/model/Model.hpp"

namespace beamrotor {

/// One prismatic piece of the line.
struct Segment {
  double length = 0;  ///< m
  std::shared_ptr<const Section> section;
  int elements = 0;       ///< element count, or 0 to use targetSize
  double targetSize = 0;  ///< largest element length (m) when elements == 0
  BeamOptions options{};  // an initializer, so that {length, section, elements} says enough
};

/// A named station along the line, at distance `at` (m) from its start.
struct NamedPoint {
  std::string name;
  double at = 0;
};

struct LineSpec {
  Eigen::Vector3d start = Eigen::Vector3d::Zero();
  Eigen::Vector3d direction = Eigen::Vector3d::UnitX();
  DofSet dofs = DofSet::planar();
  std::vector<Segment> segments;
  std::vector<NamedPoint> points;
};

/// What the builder made, in order along the line.
struct Line {
  std::vector<int> nodes;        ///< node indices from start to end
  std::vector<double> stations;  ///< distance of each node from the start (m)
  std::vector<Beam*> beams;      ///< elements from start to end (owned by the model)
};

/// Elements for a piece `piece` (m) of a segment: the segment's count shared out by length,
/// or as many as the target size needs (at least one).
int elementsFor(const Segment& segment, double piece);

/// Adds the line's nodes and beams to model and names its points. Throws
/// std::invalid_argument for a point outside the line or a non-positive length.
Line buildLine(Model& model, const LineSpec& spec);

}  // namespace beamrotor

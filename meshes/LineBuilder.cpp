#include "meshes/LineBuilder.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace beamrotor {

int elementsFor(const Segment& seg, double piece) {
  if (seg.elements > 0)
    return std::max(1, int(std::lround(seg.elements * piece / seg.length)));
  return std::max(1, int(std::ceil(piece / seg.targetSize - 1e-9)));
}

Line buildLine(Model& model, const LineSpec& spec) {
  // 1. Validate and find the segment boundaries.
  const Eigen::Vector3d dir = spec.direction.normalized();
  std::vector<double> bounds{0};
  for (const Segment& seg : spec.segments) {
    if (!(seg.length > 0) || !std::isfinite(seg.length))
      throw std::invalid_argument("segment length must be positive");
    if (seg.elements <= 0 && !(seg.targetSize > 0))
      throw std::invalid_argument("segment needs an element count or a positive element size");
    bounds.push_back(bounds.back() + seg.length);
  }
  const double total = bounds.back();
  const double tol = 1e-12 * std::max(1.0, total);
  for (const NamedPoint& p : spec.points)
    if (!(p.at >= -tol && p.at <= total + tol))
      throw std::invalid_argument("point '" + p.name + "' at " + std::to_string(p.at) +
                                  " m lies outside the line (0 to " + std::to_string(total) +
                                  " m)");

  // 2. Walk the segments, cutting each at the named points inside it.
  Line line;
  auto addNode = [&](double at) {
    line.nodes.push_back(model.addNode(spec.start + at * dir));
    line.stations.push_back(at);
  };
  addNode(0);
  // Cuts are measured from the segment's start, so a piece without named points inside is
  // the segment's own length and each element's length is piece / n to round-off, however
  // far from the origin the segment lies (stations far out have fewer digits to spare).
  for (std::size_t k = 0; k < spec.segments.size(); ++k) {
    const Segment& seg = spec.segments[k];
    std::vector<double> cuts{0};
    for (const NamedPoint& p : spec.points)
      if (p.at > bounds[k] + tol && p.at < bounds[k + 1] - tol) cuts.push_back(p.at - bounds[k]);
    std::sort(cuts.begin(), cuts.end());
    cuts.push_back(seg.length);
    for (std::size_t c = 0; c + 1 < cuts.size(); ++c) {
      const double piece = cuts[c + 1] - cuts[c];
      if (piece <= tol) continue;
      const int n = elementsFor(seg, piece);
      for (int e = 1; e <= n; ++e) {
        const double at = e < n                  ? bounds[k] + cuts[c] + piece * e / n
                          : c + 2 == cuts.size() ? bounds[k + 1]
                                                 : bounds[k] + cuts[c + 1];
        const int from = line.nodes.back();
        addNode(at);
        line.beams.push_back(&model.add<Beam>(from, line.nodes.back(), dir, piece / n,
                                              seg.section, spec.dofs, seg.options));
      }
    }
  }

  // 3. Name the points: each goes to the node nearest its station.
  for (const NamedPoint& p : spec.points) {
    const auto it = std::min_element(line.stations.begin(), line.stations.end(),
                                     [&](double a, double b) {
                                       return std::abs(a - p.at) < std::abs(b - p.at);
                                     });
    model.nameNode(p.name, line.nodes[it - line.stations.begin()]);
  }
  return line;
}

}  // namespace beamrotor

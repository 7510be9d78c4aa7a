// Sampling along line elements (see LineSampling.hpp): line coordinate, Hermite interpolation.
#include "problems/output/LineSampling.hpp"

#include <algorithm>
#include <stdexcept>

#include "fem/assembly/Recovery.hpp"

namespace beamrotor {

namespace {

const LineElement* asLine(const std::unique_ptr<Element>& e) {
  return dynamic_cast<const LineElement*>(e.get());
}

/// Cubic Hermite deflection and its slope d/dx at fraction s, from end values w and slopes t.
struct Hermite {
  double value, slope;
};
Hermite hermite(double w1, double t1, double w2, double t2, double L, double s) {
  const double s2 = s * s, s3 = s2 * s;
  const double value = (1 - 3 * s2 + 2 * s3) * w1 + L * (s - 2 * s2 + s3) * t1 +
                       (3 * s2 - 2 * s3) * w2 + L * (s3 - s2) * t2;
  const double slope = (6 * s2 - 6 * s) / L * w1 + (1 - 4 * s + 3 * s2) * t1 +
                       (6 * s - 6 * s2) / L * w2 + (3 * s2 - 2 * s) * t2;
  return {value, slope};
}

}  // namespace

std::vector<std::optional<double>> lineCoordinates(const Model& model) {
  std::vector<std::optional<double>> x(model.nodeCount());
  double furthest = 0;
  for (const auto& e : model.elements()) {
    const LineElement* line = asLine(e);
    if (!line) continue;
    const auto [a, b] = line->endNodes();
    if (!x[a]) x[a] = furthest;
    if (!x[b]) x[b] = *x[a] + line->length();
    furthest = std::max({furthest, *x[a], *x[b]});
  }
  return x;
}

std::vector<LinePlace> placesAlongLine(const Model& model, int intervalsPerElement) {
  if (intervalsPerElement < 1) throw std::invalid_argument("need at least one interval");
  const auto coordinate = lineCoordinates(model);
  std::vector<LinePlace> places;
  const auto& elements = model.elements();
  for (int i = 0; i < int(elements.size()); ++i) {
    const LineElement* line = asLine(elements[i]);
    if (!line) continue;
    const double start = *coordinate[line->endNodes()[0]];
    for (int k = 0; k <= intervalsPerElement; ++k) {
      const double s = double(k) / intervalsPerElement;
      places.push_back({i, s, start + s * line->length()});
    }
  }
  return places;
}

std::array<double, kDofKinds> displacementAt(const LineElement& element, const NodalField& field,
                                             double s) {
  // 1. End translations and rotations in the element frame (rows of R are the local axes).
  const Eigen::Matrix3d R = element.localAxes();
  const auto [n1, n2] = element.endNodes();
  const auto translation = [&](int n) -> Eigen::Vector3d {
    return R * field.row(n).head<3>().transpose();
  };
  const auto rotation = [&](int n) -> Eigen::Vector3d {
    return R * field.row(n).tail<3>().transpose();
  };
  const Eigen::Vector3d u1 = translation(n1), u2 = translation(n2);
  const Eigen::Vector3d r1 = rotation(n1), r2 = rotation(n2);
  const double L = element.length();

  // 2. Interpolate: v has slope rz, w has slope -ry (right-hand rule about local z and y).
  const Hermite v = hermite(u1.y(), r1.z(), u2.y(), r2.z(), L, s);
  const Hermite w = hermite(u1.z(), -r1.y(), u2.z(), -r2.y(), L, s);
  const Eigen::Vector3d u((1 - s) * u1.x() + s * u2.x(), v.value, w.value);
  const Eigen::Vector3d r((1 - s) * r1.x() + s * r2.x(), -w.slope, v.slope);

  // 3. Back to the global frame.
  const Eigen::Vector3d ug = R.transpose() * u, rg = R.transpose() * r;
  return {ug.x(), ug.y(), ug.z(), rg.x(), rg.y(), rg.z()};
}

std::vector<StaticStation> sampleStatics(const Model& model, const NodalField& displacement,
                                         int intervalsPerElement) {
  const std::vector<LinePlace> places = placesAlongLine(model, intervalsPerElement);
  const std::vector<BeamStation> recovered =
      recoverBeamFields(model, displacement, intervalsPerElement);
  if (recovered.size() != places.size())
    throw std::logic_error("recoverBeamFields sampled different stations");
  std::vector<StaticStation> stations;
  stations.reserve(places.size());
  for (std::size_t i = 0; i < places.size(); ++i) {
    const LinePlace& p = places[i];
    if (recovered[i].element != p.element)
      throw std::logic_error("recoverBeamFields sampled different elements");
    const auto& line = static_cast<const LineElement&>(*model.elements()[p.element]);
    stations.push_back({p, displacementAt(line, displacement, p.s), recovered[i].forces,
                        recovered[i].stress, recovered[i].shear});
  }
  return stations;
}

namespace {

std::optional<StaticStation> largest(const std::vector<StaticStation>& stations,
                                     double StaticStation::*value) {
  if (stations.empty()) return std::nullopt;
  return *std::max_element(
      stations.begin(), stations.end(),
      [&](const StaticStation& a, const StaticStation& b) { return a.*value < b.*value; });
}

}  // namespace

std::optional<StaticStation> largestStress(const std::vector<StaticStation>& stations) {
  return largest(stations, &StaticStation::stress);
}

std::optional<StaticStation> largestShear(const std::vector<StaticStation>& stations) {
  return largest(stations, &StaticStation::shear);
}

}  // namespace beamrotor

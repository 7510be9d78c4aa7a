#include "meshes/TrainBuilder.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "elements/GearMesh.hpp"
#include "elements/PointInertia.hpp"
#include "elements/Spring.hpp"

namespace beamrotor {

namespace {

double shaftLength(const TrainShaft& s) {
  double L = 0;
  for (const Segment& g : s.segments) L += g.length;
  return L;
}

int shaftIndex(const TrainSpec& spec, const std::string& name) {
  for (std::size_t i = 0; i < spec.shafts.size(); ++i)
    if (spec.shafts[i].name == name) return int(i);
  throw std::invalid_argument("no shaft named '" + name + "'");
}

int stationNode(const Model& model, const TrainStation& s) {
  const auto& names = model.namedNodes();
  const auto it = names.find(s.name());
  if (it == names.end()) throw std::invalid_argument("no station '" + s.name() + "'");
  return it->second;
}

}  // namespace

TrainMesh buildTrain(Model& model, const TrainSpec& spec) {
  TrainMesh mesh;
  double longest = 0;
  for (const TrainShaft& s : spec.shafts) longest = std::max(longest, shaftLength(s));
  double x0 = 0;
  for (const TrainShaft& s : spec.shafts) {
    LineSpec line;
    line.start = Eigen::Vector3d(x0, 0, 0);
    line.dofs = DofSet::torsion();
    line.segments = s.segments;
    const double L = shaftLength(s);
    line.points = {{s.name + ".start", 0}, {s.name + ".end", L}};
    for (const NamedPoint& p : s.stations) line.points.push_back({s.name + "." + p.name, p.at});
    mesh.shafts.push_back(buildLine(model, line));
    x0 += L + longest / 10;
  }
  for (const TrainDisk& d : spec.disks)
    model.add<PointInertia>(stationNode(model, d.at), DofSet::torsion(), 0.0, d.Jp);
  for (const TrainJoint& j : spec.couplings) {
    model.add<Spring>(NodeDof{stationNode(model, j.from), Dof::rx},
                      NodeDof{stationNode(model, j.to), Dof::rx}, j.stiffness, j.damping);
    mesh.couplings.push_back(int(model.elements().size()) - 1);
    model.nameElement(j.name, mesh.couplings.back());
  }
  for (const TrainJoint& j : spec.gears) {
    model.add<GearMesh>(stationNode(model, j.from), stationNode(model, j.to), j.ratio,
                        j.stiffness, j.damping);
    mesh.gears.push_back(int(model.elements().size()) - 1);
    model.nameElement(j.name, mesh.gears.back());
  }
  return mesh;
}

std::vector<double> shaftSpeedRatios(const TrainSpec& spec) {
  const std::size_t n = spec.shafts.size();
  std::vector<double> ratio(n, 0);
  if (n == 0) return ratio;
  ratio[0] = 1;
  // Spread the speed along the joints until nothing changes (a train has few joints).
  for (bool changed = true; changed;) {
    changed = false;
    const auto spread = [&](const TrainJoint& j) {
      const int a = shaftIndex(spec, j.from.shaft), b = shaftIndex(spec, j.to.shaft);
      if (ratio[a] > 0 && ratio[b] == 0) {
        ratio[b] = ratio[a] / j.ratio;
        changed = true;
      } else if (ratio[b] > 0 && ratio[a] == 0) {
        ratio[a] = ratio[b] * j.ratio;
        changed = true;
      } else if (ratio[a] > 0 && std::abs(ratio[a] / j.ratio - ratio[b]) > 1e-12 * ratio[b]) {
        throw std::invalid_argument("'" + j.name + "' joins shafts '" + j.from.shaft + "' and '" +
                                    j.to.shaft +
                                    "' whose speeds the other joints already fix at another ratio");
      }
    };
    for (const TrainJoint& j : spec.couplings) spread(j);
    for (const TrainJoint& j : spec.gears) spread(j);
  }
  for (std::size_t i = 0; i < n; ++i)
    if (ratio[i] == 0)
      throw std::invalid_argument("shaft '" + spec.shafts[i].name +
                                  "' is joined to the first shaft by no coupling or gear");
  return ratio;
}

}  // namespace beamrotor

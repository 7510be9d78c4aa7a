#include "problems/bench/StandardModels.hpp"

#include <cmath>
#include <numbers>

#include "elements/Beam.hpp"
#include "elements/Bearing.hpp"
#include "elements/PointInertia.hpp"
#include "elements/Spring.hpp"
#include "meshes/LineBuilder.hpp"

namespace beamrotor {

namespace {

Material steel() { return Material::fromEnu("steel", 210e9, 0.3, 7850); }

/// The benchmark rotor's data (SI units), shared by the rotor and its planar twin.
struct RotorData {
  static constexpr double length = 1.5, diameter = 0.05;
  static constexpr double diskMass = 20, diskJp = 0.225, diskJd = 0.1125;  // 0.3 m thin disk
  static constexpr double bearingStiffness = 1e7, gravity = 9.81;
  static constexpr const char* disks[] = {"disk1", "disk2", "disk3"};
  static constexpr const char* bearings[] = {"A", "B"};
};

/// The shaft in four equal segments (the disks at their joints) and the disks on it.
Line rotorShaft(Model& m, int elements, DofSet dofs) {
  using R = RotorData;
  const auto section = std::make_shared<const Section>(
      Section::circle("shaft 50", steel(), R::diameter));
  LineSpec spec;
  spec.dofs = dofs;
  for (int s = 0; s < 4; ++s)
    spec.segments.push_back({R::length / 4, section, elements / 4, 0,
                             {BeamTheory::timoshenko, MassModel::consistent, true}});
  spec.points = {{R::bearings[0], 0},          {R::disks[0], R::length / 4},
                 {R::disks[1], R::length / 2}, {R::disks[2], 3 * R::length / 4},
                 {R::bearings[1], R::length}};
  Line line = buildLine(m, spec);
  for (const char* disk : R::disks)
    m.add<PointInertia>(m.node(disk), dofs, R::diskMass, R::diskJp, R::diskJd);
  return line;
}

int rotorElements(int elements) { return 4 * std::max(1, (elements + 3) / 4); }

}  // namespace

PlanarBenchModel planarBenchModel(int elements) {
  constexpr double span = 0.6, q = -1000.0, side = 0.02;
  constexpr int perSpan = 10;
  PlanarBenchModel out;
  out.spans = std::max(1, (elements + perSpan - 1) / perSpan);
  out.model = std::make_unique<Model>();
  Model& m = *out.model;
  const auto section = std::make_shared<const Section>(
      Section::rectangle("20x20", steel(), side, side));
  // One segment per span: every element is span / perSpan long to round-off, at any distance
  // from the origin (LineBuilder.hpp), and node s * perSpan ends span s.
  LineSpec spec;
  spec.segments.assign(out.spans, {span, section, perSpan});
  for (Beam* beam : buildLine(m, spec).beams) beam->setDistributedLoad({0, q, 0});
  for (int s = 0; s <= out.spans; ++s)
    m.addSupport({"pin" + std::to_string(s), s * perSpan, {{Dof::ux, 0}, {Dof::uy, 0}}});
  out.midspanNode = (out.spans / 2) * perSpan + perSpan / 2;
  const double EI = section->EIz();
  out.exactMidspanW = q * std::pow(span, 4) / (384 * EI);
  out.exactLowestHz = std::numbers::pi / (2 * span * span) * std::sqrt(EI / section->rhoA());
  return out;
}

GridBenchModel gridBenchModel(int bays) {
  constexpr int perEdge = 4;
  constexpr double bay = 1.0, load = 1000.0;
  GridBenchModel out;
  out.bays = std::max(1, bays);
  out.side = perEdge * out.bays + 1;
  out.model = std::make_unique<Model>();
  Model& m = *out.model;
  const auto section =
      std::make_shared<const Section>(Section::tube("tube 60x4", steel(), 0.060, 0.004));
  const int side = out.side;
  const double h = bay / perEdge;
  const auto onLine = [](int k) { return k % perEdge == 0; };
  const auto onBoundary = [side](int k) { return k == 0 || k == side - 1; };

  // 1. Nodes row by row (banded numbering), pinned on the boundary, loaded everywhere.
  out.lattice.assign(std::size_t(side) * side, -1);
  for (int j = 0; j < side; ++j)
    for (int i = 0; i < side; ++i) {
      if (!onLine(i) && !onLine(j)) continue;
      const int node = m.addNode({i * h, j * h, 0});
      out.lattice[std::size_t(j) * side + i] = node;
      if (onBoundary(i) || onBoundary(j))
        m.addSupport({"pin" + std::to_string(node), node,
                      {{Dof::ux, 0}, {Dof::uy, 0}, {Dof::uz, 0}}});
      m.addLoad({node, Dof::uz, -load});
      out.totalLoad += load;
    }

  // 2. Beams along x on every grid line j, then along y on every grid line i.
  for (int j = 0; j < side; j += perEdge)
    for (int i = 0; i + 1 < side; ++i) {
      const int a = out.nodeAt(i, j), b = out.nodeAt(i + 1, j);
      m.add<Beam>(a, m.nodes()[a], b, m.nodes()[b], section, DofSet::frame3d());
    }
  for (int i = 0; i < side; i += perEdge)
    for (int j = 0; j + 1 < side; ++j) {
      const int a = out.nodeAt(i, j), b = out.nodeAt(i, j + 1);
      m.add<Beam>(a, m.nodes()[a], b, m.nodes()[b], section, DofSet::frame3d());
    }
  return out;
}

long long gridFreeDofs(int bays) {
  const long long n = bays, nodes = (4 * n + 1) * (4 * n + 1) - 9 * n * n;
  return 6 * nodes - 3 * 16 * n;
}

long long gridElements(int bays) { return 8LL * bays * (bays + 1); }

int closestSize(long long target, long long (*count)(int)) {
  int n = 1;
  while (count(n) < target) ++n;
  if (n > 1 && target - count(n - 1) <= count(n) - target) --n;
  return n;
}

RotorBenchModel rotorBenchModel(int elements) {
  using R = RotorData;
  RotorBenchModel out;
  out.elements = rotorElements(elements);
  out.model = std::make_unique<Model>();
  Model& m = *out.model;
  const Line line = rotorShaft(m, out.elements, DofSet::lateral());
  out.bearingStiffness = R::bearingStiffness;
  for (const char* name : R::bearings) {
    out.bearingNodes.push_back(m.node(name));
    m.add<Bearing>(m.node(name), BearingCoefficients::isotropic(R::bearingStiffness));
  }
  // Self weight along -y: the shaft's as a distributed load, the disks' at their nodes.
  const double rhoA = line.beams.front()->section().rhoA();
  for (Beam* beam : line.beams) beam->setDistributedLoad({0, -rhoA * R::gravity, 0});
  for (const char* disk : R::disks) m.addLoad({m.node(disk), Dof::uy, -R::diskMass * R::gravity});
  out.weight = (rhoA * R::length + 3 * R::diskMass) * R::gravity;
  return out;
}

std::unique_ptr<Model> rotorPlanarTwin(int elements) {
  using R = RotorData;
  auto model = std::make_unique<Model>();
  Model& m = *model;
  rotorShaft(m, rotorElements(elements), DofSet::planar());
  for (const char* name : R::bearings)
    m.add<Spring>(NodeDof{m.node(name), Dof::uy}, R::bearingStiffness);
  for (int node = 0; node < m.nodeCount(); ++node)
    m.addSupport({"axial" + std::to_string(node), node, {{Dof::ux, 0}}});
  return model;
}

}  // namespace beamrotor

#include "problems/scenes/FormeShaft.hpp"

#include <cmath>
#include <limits>
#include <stdexcept>

#include "elements/Bearing.hpp"
#include "elements/PointInertia.hpp"
#include "elements/Spring.hpp"
#include "fem/assembly/Assembly.hpp"
#include "fem/model/DofMap.hpp"

namespace beamrotor {

std::string_view paperModeName(int ascending) {
  return ascending == 0 ? "k2 ('-' root)" : "k1 ('+' root)";
}

std::string_view formeModeKindName(FormeModeKind k) {
  switch (k) {
    case FormeModeKind::coupled:
      return "coupled";
    case FormeModeKind::bounce:
      return "bounce";
    case FormeModeKind::rocking:
      return "rocking";
  }
  return "coupled";
}

std::array<FormeShaftMode, 2> formeShaftModes(const FormeShaftRigid& s) {
  if (!(s.m > 0) || !(s.J > 0))
    throw std::invalid_argument("forme shaft: mass and moment of inertia must be positive");
  if (!(s.C1 >= 0) || !(s.C2 >= 0))
    throw std::invalid_argument("forme shaft: spring stiffnesses must be non-negative");
  const double a = s.a(), b = s.b(), d = s.d(), r2 = s.rho2(), dr = d / r2;

  // 1. Roots of the quadratic in k^2, written without cancellation: the discriminant as a
  //    sum of squares, the smaller root from the product of the roots (a d - b^2) / rho^2.
  const double half = std::hypot((a - dr) / 2, b / std::sqrt(r2));
  const double hi = (a + dr) / 2 + half;
  const double lo = hi > 0 ? std::max(0.0, (a * dr - b * b / r2) / hi) : 0.0;
  const bool decoupled =
      std::abs(b) <= kFormeDecoupled * (s.C1 * std::abs(s.l1) + s.C2 * std::abs(s.l2)) / s.m;

  std::array<FormeShaftMode, 2> modes;
  for (int i = 0; i < 2; ++i) {
    FormeShaftMode& mode = modes[i];
    const double k2 = i == 0 ? lo : hi;
    mode.k = std::sqrt(k2);
    // 2. The amplitudes: each row of (K - k^2 M) (z, phi) = 0 gives a null vector,
    //      row 1: (a - k^2) z + b phi = 0             ->  (z, phi) = (b, k^2 - a),
    //      row 2: b z + (d - rho^2 k^2) phi = 0       ->  (z, phi) = (rho^2 k^2 - d, b),
    //    and at b = 0 one of them vanishes (the paper's n = b / (k^2 - a) is 0/0 for the
    //    bounce root). Taking the longer one (in the norm z^2 + rho^2 phi^2, row 2 divided
    //    by rho to match units) is exact in every case and never divides by a small number.
    double z1 = b, p1 = k2 - a;
    double z2 = (r2 * k2 - d) / std::sqrt(r2), p2 = b / std::sqrt(r2);
    const double e1 = z1 * z1 + r2 * p1 * p1, e2 = z2 * z2 + r2 * p2 * p2;
    double z = e1 >= e2 ? z1 : z2, phi = e1 >= e2 ? p1 : p2;
    if (e1 == 0 && e2 == 0) {
      // b = 0 and a = d / rho^2: a double root, any combination is a mode.
      z = i == 0 ? 1 : 0;
      phi = i == 0 ? 0 : 1;
    }
    if (decoupled) {  // b is round-off: the modes are pure bounce and pure rocking
      const bool bounce = std::abs(z) >= std::sqrt(r2) * std::abs(phi);
      mode.kind = bounce ? FormeModeKind::bounce : FormeModeKind::rocking;
      z = bounce ? 1 : 0;
      phi = bounce ? 0 : 1;
    }
    const double norm = std::sqrt(z * z + r2 * phi * phi);
    const double sign =
        std::abs(z) >= std::sqrt(r2) * std::abs(phi) ? (z < 0 ? -1 : 1) : (phi < 0 ? -1 : 1);
    mode.z = sign * z / norm;
    mode.phi = sign * phi / norm;
    mode.n = mode.phi != 0 ? mode.z / mode.phi : std::numeric_limits<double>::infinity();
    // 3. Dynamic loads at these amplitudes.
    mode.FA = s.C1 * (mode.z - s.l1 * mode.phi);
    mode.FB = s.C2 * (mode.z + s.l2 * mode.phi);
    mode.inertiaForce = -s.m * k2 * mode.z;
    mode.inertiaMoment = -s.J * k2 * mode.phi;
  }
  return modes;
}

double formeShaftWhirl(const FormeShaftRigid& s, double Jp, double speed, int sense) {
  const double kPhi = s.C1 * s.l1 * s.l1 + s.C2 * s.l2 * s.l2;
  const double g = Jp * speed;
  return (sense * g + std::sqrt(g * g + 4 * s.J * kPhi)) / (2 * s.J);
}

FormeShaftModel buildFormeShaft(const FormeShaftDesign& d, DofSet dofs) {
  if (!(dofs == DofSet::planar()) && !(dofs == DofSet::lateral()))
    throw std::invalid_argument("forme shaft: planar or lateral dofs only");
  if (!(d.bearingInset > 0 && d.bearingInset < d.operatorJournal &&
        d.bearingInset < d.driveJournal && d.gearInset > 0 && d.gearInset <= d.driveJournal))
    throw std::invalid_argument("forme shaft: bearings and gear must sit on the journals");

  // 1. Sections and the three segments: operator journal, barrel, drive journal.
  const Material steel = Material::fromEnu("steel", d.E, d.nu, d.rho);
  const auto journal =
      std::make_shared<Section>(Section::circle("journal", steel, d.journalDiameter));
  const auto barrel = std::make_shared<Section>(
      d.barrelBore > 0
          ? Section::tube("barrel", steel, d.barrelDiameter, (d.barrelDiameter - d.barrelBore) / 2)
          : Section::circle("barrel", steel, d.barrelDiameter));
  const BeamOptions beam{BeamTheory::timoshenko, MassModel::consistent, true};
  FormeShaftModel fe;
  fe.xA = d.operatorJournal - d.bearingInset;
  fe.xB = d.operatorJournal + d.barrelLength + d.bearingInset;
  LineSpec spec;
  spec.dofs = dofs;
  spec.segments = {{d.operatorJournal, journal, 0, d.elementSize, beam},
                   {d.barrelLength, barrel, 0, d.elementSize, beam},
                   {d.driveJournal, journal, 0, d.elementSize, beam}};
  spec.points = {
      {"A", fe.xA}, {"B", fe.xB}, {"gear", d.operatorJournal + d.barrelLength + d.gearInset}};
  fe.line = buildLine(fe.model, spec);
  fe.nodeA = fe.model.node("A");
  fe.nodeB = fe.model.node("B");
  fe.nodeGear = fe.model.node("gear");

  // 2. The gear and the bearings.
  fe.model.add<PointInertia>(fe.nodeGear, dofs, d.gearMass, d.gearJp, d.gearJd);
  if (dofs == DofSet::planar()) {
    fe.model.add<Spring>(NodeDof{fe.nodeA, Dof::uy}, d.C1);
    fe.model.add<Spring>(NodeDof{fe.nodeB, Dof::uy}, d.C2);
    fe.model.addSupport({"thrust", fe.nodeA, {{Dof::ux, 0}}});
  } else {
    fe.model.add<Bearing>(fe.nodeA, BearingCoefficients::isotropic(d.C1));
    fe.model.add<Bearing>(fe.nodeB, BearingCoefficients::isotropic(d.C2));
  }
  return fe;
}

RigidBodyProperties rigidBodyProperties(const Model& model) {
  const DofMap dofs(model);
  const SparseAssembler assembler(model, dofs);
  const SparseMatrix M = assembler.assemble(MatrixKind::mass);
  const SparseMatrix G = assembler.assemble(MatrixKind::gyroscopic);
  const int n = dofs.freeCount();
  // Rigid motions of the free dofs: translation along y, rotations about z (through x0) and
  // about y (uz = -(x - x0) with ry = 1, since dw/dx = -ry).
  auto rigid = [&](Dof kind, double x0) {
    Eigen::VectorXd r = Eigen::VectorXd::Zero(n);
    for (int eq = 0; eq < n; ++eq) {
      const NodeDof& nd = dofs.dofOf(eq);
      const double x = model.nodes()[nd.node].x() - x0;
      if (kind == Dof::uy && nd.dof == Dof::uy) r[eq] = 1;
      if (kind == Dof::rz && nd.dof == Dof::uy) r[eq] = x;
      if (kind == Dof::rz && nd.dof == Dof::rz) r[eq] = 1;
      if (kind == Dof::ry && nd.dof == Dof::uz) r[eq] = -x;
      if (kind == Dof::ry && nd.dof == Dof::ry) r[eq] = 1;
    }
    return r;
  };
  RigidBodyProperties p;
  const Eigen::VectorXd t = rigid(Dof::uy, 0);
  p.m = t.dot(M * t);
  p.xG = t.dot(M * rigid(Dof::rz, 0)) / p.m;
  const Eigen::VectorXd rz = rigid(Dof::rz, p.xG);
  p.J = rz.dot(M * rz);
  if (G.nonZeros() > 0) p.Jp = rigid(Dof::ry, p.xG).dot(G * rz);
  return p;
}

FormeShaftRigid rigidModel(const RigidBodyProperties& body, double xA, double xB, double C1,
                           double C2) {
  return {body.m, body.J, C1, C2, body.xG - xA, xB - body.xG};
}

}  // namespace beamrotor

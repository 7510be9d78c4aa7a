#include "fem/rotor/RotorSystem.hpp"

#include <algorithm>

#include "fem/assembly/ReducedSystem.hpp"
#include "fem/model/Model.hpp"

namespace beamrotor {

namespace {

/// Position of entry (row, col) in A's value array; the entry must be in the pattern.
int valueIndex(const SparseMatrix& A, int row, int col) {
  const int* first = A.innerIndexPtr() + A.outerIndexPtr()[col];
  const int* last = A.innerIndexPtr() + A.outerIndexPtr()[col + 1];
  const int* it = std::lower_bound(first, last, row);
  return it != last && *it == row ? int(it - A.innerIndexPtr()) : -1;
}

/// The element matrix, or zeros of the element's size when it has none.
ElementMatrix orZero(ElementMatrix m, int n) {
  return m.size() == 0 ? ElementMatrix(ElementMatrix::Zero(n, n)) : m;
}

}  // namespace

RotorSystem::RotorSystem(const Model& model, ProportionalDamping damping)
    : model_(model), dofs_(model), proportional_(damping) {
  // 1. Assemble every kind over the shared pattern, speed-dependent elements at rest.
  const SparseAssembler assembler(model, dofs_);
  M_ = assembler.assemble(MatrixKind::mass);
  G_ = assembler.assemble(MatrixKind::gyroscopic);
  K0_ = assembler.assemble(MatrixKind::stiffness);
  // A shaft's given axial force (Beam::setAxialPreload): its geometric stiffness at rest
  // (the zero state adds no force of its own), on K's pattern.
  K0_ += assembler.assembleGeometric(Eigen::VectorXd::Zero(dofs_.size()));
  C0_ = assembler.assemble(MatrixKind::damping);

  // 2. Remember where each speed-dependent element's entries live in the pattern.
  for (const auto& e : model.elements()) {
    const auto* sd = dynamic_cast<const SpeedDependentElement*>(e.get());
    if (!sd) continue;
    const auto d = sd->dofs();
    const int n = int(d.size());
    SpeedTerm term{sd, {}, orZero(sd->stiffnessAt(0), n), orZero(sd->dampingAt(0), n)};
    for (int b = 0; b < n; ++b)
      for (int a = 0; a < n; ++a) {
        const int row = dofs_.equation(d[a]), col = dofs_.equation(d[b]);
        term.slots.push_back(dofs_.isFree(row) && dofs_.isFree(col) ? valueIndex(K0_, row, col)
                                                                    : -1);
      }
    terms_.push_back(std::move(term));
  }
}

SparseMatrix RotorSystem::atSpeed(const SparseMatrix& A, double speed, bool stiffness) const {
  SparseMatrix out = A;
  for (const SpeedTerm& t : terms_) {
    const int n = int(t.k0.rows());
    const ElementMatrix now =
        orZero(stiffness ? t.element->stiffnessAt(speed) : t.element->dampingAt(speed), n);
    const ElementMatrix& rest = stiffness ? t.k0 : t.c0;
    for (int b = 0; b < n; ++b)
      for (int a = 0; a < n; ++a)
        if (const int slot = t.slots[b * n + a]; slot >= 0)
          out.valuePtr()[slot] += now(a, b) - rest(a, b);
  }
  return out;
}

SparseMatrix RotorSystem::stiffness(double speed) const {
  return atSpeed(K0_, speed, true);
}

SparseMatrix RotorSystem::damping(double speed) const {
  SparseMatrix C = atSpeed(C0_, speed, false);
  if (proportional_.alpha != 0) C += proportional_.alpha * M_;
  if (proportional_.beta != 0) C += proportional_.beta * stiffness(speed);
  return C;
}

SystemSize RotorSystem::systemSize(double factorEntries) const {
  return beamrotor::systemSize(model_, dofs_, K0_.nonZeros(), factorEntries);
}

}  // namespace beamrotor

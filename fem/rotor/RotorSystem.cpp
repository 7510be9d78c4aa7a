#include "fem/rotor/RotorSystem.hpp"

#include <algorithm>
#include <optional>
#include <utility>
#include <stdexcept>
#include <string>
#include <vector>

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
    whirlDependent_ = whirlDependent_ || sd->dependsOnWhirl();
    for (int a = n - sd->ownDofs(); a < n; ++a)
      if (const int eq = dofs_.equation(d[a]); dofs_.isFree(eq)) {
        if (bearingOwn_.empty()) bearingOwn_.assign(std::size_t(size()), false);
        bearingOwn_[std::size_t(eq)] = true;
      }
    terms_.push_back(std::move(term));
  }
  if (proportional_.internal != 0) assembleShaft();
}

namespace {

/// The quarter turn about the shaft's axis x at one dof: the dof whose value R puts here and
/// its sign, (R q)_uy = q_uz, (R q)_uz = -q_uy, (R q)_ry = q_rz, (R q)_rz = -q_ry; none for
/// ux and rx, which a turn about x leaves alone and which so carry no circulatory term.
std::optional<std::pair<Dof, double>> quarterTurnSource(Dof d) {
  switch (d) {
    case Dof::uy: return std::pair{Dof::uz, 1.0};
    case Dof::uz: return std::pair{Dof::uy, -1.0};
    case Dof::ry: return std::pair{Dof::rz, 1.0};
    case Dof::rz: return std::pair{Dof::ry, -1.0};
    default: return std::nullopt;
  }
}

}  // namespace

void RotorSystem::assembleShaft() {
  shaft_ = K0_;
  shaft_.coeffs().setZero();
  circulatory_ = shaft_;
  auto add = [&](SparseMatrix& A, int row, int col, double v) {
    if (!dofs_.isFree(row) || !dofs_.isFree(col) || v == 0) return;
    const int slot = valueIndex(A, row, col);
    if (slot < 0)  // the pattern holds every dof pair of an element's nodes
      throw std::logic_error("internal damping: an entry outside the rotor's pattern");
    A.valuePtr()[slot] += v;
  };
  for (const auto& e : model_.elements()) {
    if (!e->asLineElement()) continue;  // the shaft: beams spin, springs and bearings do not
    const auto d = e->dofs();
    const int n = int(d.size());
    const ElementMatrix k = e->stiffness();
    for (int b = 0; b < n; ++b) {
      const int col = dofs_.equation(d[b]);
      for (int a = 0; a < n; ++a) add(shaft_, dofs_.equation(d[a]), col, k(a, b));
    }
    for (int b = 0; b < n; ++b) {
      const auto source = quarterTurnSource(d[b].dof);
      if (!source) continue;
      // Row i of R q reads q at source(i): R(i, source(i)) = sign(i). Hence column
      // source(i) of K_s R is sign(i) times column i of K_s.
      int target = -1;
      for (int c = 0; c < n; ++c)
        if (d[c].node == d[b].node && d[c].dof == source->first) target = c;
      if (target < 0) continue;  // a lateral dof without its partner: no turn there
      const int col = dofs_.equation(d[target]);
      for (int a = 0; a < n; ++a)
        add(circulatory_, dofs_.equation(d[a]), col, source->second * k(a, b));
    }
  }
}

SparseMatrix RotorSystem::atSpeed(const SparseMatrix& A, double speed, bool stiffness,
                                  const std::complex<double>* lambda) const {
  SparseMatrix out = A;
  for (const SpeedTerm& t : terms_) {
    const int n = int(t.k0.rows());
    ElementMatrix now;
    if (lambda && t.element->dependsOnWhirl()) {
      EigenvalueMatrices at = t.element->atEigenvalue(speed, *lambda);
      now = orZero(stiffness ? std::move(at.stiffness) : std::move(at.damping), n);
    } else {
      now = orZero(stiffness ? t.element->stiffnessAt(speed) : t.element->dampingAt(speed), n);
    }
    const ElementMatrix& rest = stiffness ? t.k0 : t.c0;
    for (int b = 0; b < n; ++b)
      for (int a = 0; a < n; ++a)
        if (const int slot = t.slots[b * n + a]; slot >= 0)
          out.valuePtr()[slot] += now(a, b) - rest(a, b);
  }
  return out;
}

SparseMatrix RotorSystem::stiffness(double speed) const { return stiffnessAt(speed, nullptr); }

SparseMatrix RotorSystem::stiffness(double speed, std::complex<double> lambda) const {
  return stiffnessAt(speed, &lambda);
}

SparseMatrix RotorSystem::damping(double speed) const { return dampingAt(speed, nullptr); }

SparseMatrix RotorSystem::damping(double speed, std::complex<double> lambda) const {
  return dampingAt(speed, &lambda);
}

SparseMatrix RotorSystem::stiffnessAt(double speed, const std::complex<double>* lambda) const {
  SparseMatrix K = atSpeed(K0_, speed, true, lambda);
  if (proportional_.internal != 0 && speed != 0)
    K += (speed * proportional_.internal) * circulatory_;
  if (crossCoupling_.size() > 0) K += crossCoupling_;
  return K;
}

void RotorSystem::setCrossCoupling(int node, double q) {
  if (node < 0 || node >= model_.nodeCount())
    throw std::invalid_argument("cross-coupling at node " + std::to_string(node) +
                                ": no such node");
  const int y = dofs_.equation(node, Dof::uy), z = dofs_.equation(node, Dof::uz);
  if (y < 0 || z < 0 || !dofs_.isFree(y) || !dofs_.isFree(z))
    throw std::invalid_argument("cross-coupling at node " + std::to_string(node) +
                                ": its uy and uz must both be free");
  // Both entries stay in the pattern whatever q (0 included), so that every Q shares it.
  std::vector<Eigen::Triplet<double>> t{{y, z, q}, {z, y, -q}};
  crossCoupling_ = SparseMatrix(size(), size());
  crossCoupling_.setFromTriplets(t.begin(), t.end());
}

SparseMatrix RotorSystem::dampingAt(double speed, const std::complex<double>* lambda) const {
  SparseMatrix C = atSpeed(C0_, speed, false, lambda);
  if (proportional_.alpha != 0) C += proportional_.alpha * M_;
  if (proportional_.beta != 0) C += proportional_.beta * atSpeed(K0_, speed, true, lambda);
  if (proportional_.internal != 0) C += proportional_.internal * shaft_;
  return C;
}

SystemSize RotorSystem::systemSize(double factorEntries) const {
  return beamrotor::systemSize(model_, dofs_, K0_.nonZeros(), factorEntries);
}

}  // namespace beamrotor

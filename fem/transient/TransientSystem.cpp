#include "fem/transient/TransientSystem.hpp"

#include <sstream>
#include <stdexcept>

#include "fem/assembly/ReducedSystem.hpp"
#include "fem/solvers/Errors.hpp"
#include "fem/solvers/SparseLU.hpp"

namespace beamrotor {

namespace {

void requireNode(const Model& model, int node, const std::string& what) {
  if (node < 0 || node >= model.nodeCount())
    throw std::invalid_argument(what + " refers to node " + std::to_string(node) +
                                ", which the model does not have");
}

}  // namespace

TransientSystem::TransientSystem(const Model& model, const TransientOptions& options)
    : model_(model), dofs_(model) {
  // 1. The free-free matrices, all on the assembler's one pattern (so sums stay cheap).
  const SparseAssembler assembler(model, dofs_);
  K_ = assembler.assemble(MatrixKind::stiffness);
  M_ = assembler.assemble(MatrixKind::mass);
  C_ = assembler.assemble(MatrixKind::damping);
  if (options.rayleighMass != 0 || options.rayleighStiffness != 0)
    C_ += options.rayleighMass * M_ + options.rayleighStiffness * K_;
  for (int k = 0; k < C_.outerSize() && !damped_; ++k)
    for (SparseMatrix::InnerIterator it(C_, k); it; ++it)
      if (it.value() != 0) damped_ = true;

  // 2. Loads: the model's own (constant unless a factor is given) and the time loads.
  modelLoad_ = loadVector(model, dofs_).head(dofs_.freeCount());
  modelLoadFactor_ = options.modelLoadFactor;
  for (const TimeLoad& load : options.loads) {
    if (!load.factor) throw std::invalid_argument("time load '" + load.name + "' has no factor");
    Pattern p{{}, load.factor};
    for (const NodalLoad& l : load.pattern) {
      requireNode(model, l.node, "time load '" + load.name + "'");
      const int eq = dofs_.equation(l.node, l.dof);
      if (eq < 0)
        throw std::invalid_argument("time load '" + load.name + "' acts on " +
                                    model.describe({l.node, l.dof}) + ", which no element carries");
      if (dofs_.isFree(eq)) p.entries.emplace_back(eq, l.value);  // on a support: no motion
    }
    timeLoads_.push_back(std::move(p));
  }

  // 3. Supports: constant prescribed values and motions push on the free dofs through the
  // free-constrained coupling blocks.
  const int nf = dofs_.freeCount();
  uConstrained_ = prescribedValues(model, dofs_).tail(dofs_.constrainedCount());
  Eigen::VectorXd uStatic = uConstrained_;
  for (const SupportMotion& m : options.supportMotions) {
    requireNode(model, m.node, "a support motion");
    const int eq = dofs_.equation(m.node, m.dof);
    if (eq < 0 || !dofs_.isConstrained(eq))
      throw std::invalid_argument("a support motion acts on " + model.describe({m.node, m.dof}) +
                                  ", which no support holds");
    if (!m.displacement || !m.velocity || !m.acceleration)
      throw std::invalid_argument("the support motion of " + model.describe({m.node, m.dof}) +
                                  " needs its displacement, velocity and acceleration");
    motions_.emplace_back(eq - nf, m);
    uStatic[eq - nf] = 0;
  }
  staticPush_ = Eigen::VectorXd::Zero(nf);
  if (uStatic.any() || !motions_.empty()) {
    Kfc_ = couplingBlock(MatrixKind::stiffness);
    staticPush_ = -(Kfc_ * uStatic);
  }
  if (!motions_.empty()) {
    Mfc_ = couplingBlock(MatrixKind::mass);
    Cfc_ = couplingBlock(MatrixKind::damping);
    if (options.rayleighMass != 0 || options.rayleighStiffness != 0)
      Cfc_ += options.rayleighMass * Mfc_ + options.rayleighStiffness * Kfc_;
  }
}

SparseMatrix TransientSystem::couplingBlock(MatrixKind kind) const {
  const int nf = dofs_.freeCount();
  std::vector<Eigen::Triplet<double>> triplets;
  for (const auto& e : model_.elements()) {
    const ElementMatrix ke = elementMatrix(*e, kind);
    if (ke.size() == 0) continue;
    const auto d = e->dofs();
    for (int b = 0; b < int(d.size()); ++b) {
      const int col = dofs_.equation(d[b]);
      if (!dofs_.isConstrained(col)) continue;
      for (int a = 0; a < int(d.size()); ++a) {
        const int row = dofs_.equation(d[a]);
        if (dofs_.isFree(row) && ke(a, b) != 0) triplets.emplace_back(row, col - nf, ke(a, b));
      }
    }
  }
  SparseMatrix block(nf, dofs_.constrainedCount());
  block.setFromTriplets(triplets.begin(), triplets.end());
  return block;
}

void TransientSystem::force(double t, Eigen::VectorXd& f) const {
  f = staticPush_;
  f += (modelLoadFactor_ ? modelLoadFactor_(t) : 1.0) * modelLoad_;
  for (const Pattern& p : timeLoads_) {
    const double factor = p.factor(t);
    for (const auto& [eq, value] : p.entries) f[eq] += factor * value;
  }
  if (motions_.empty()) return;
  Eigen::VectorXd uc = Eigen::VectorXd::Zero(dofs_.constrainedCount()), vc = uc, ac = uc;
  for (const auto& [c, m] : motions_) {
    uc[c] = m.displacement(t);
    vc[c] = m.velocity(t);
    ac[c] = m.acceleration(t);
  }
  f -= Kfc_ * uc + Cfc_ * vc + Mfc_ * ac;
}

double TransientSystem::supportValue(int eq, double t, int derivative) const {
  const int c = eq - dofs_.freeCount();
  for (const auto& [index, m] : motions_)
    if (index == c)
      return derivative == 0   ? m.displacement(t)
             : derivative == 1 ? m.velocity(t)
                               : m.acceleration(t);
  return derivative == 0 ? uConstrained_[c] : 0.0;
}

Eigen::VectorXd TransientSystem::freeVector(const NodalField& field, const char* what) const {
  Eigen::VectorXd x = Eigen::VectorXd::Zero(dofs_.freeCount());
  if (field.size() == 0) return x;
  if (field.rows() != model_.nodeCount())
    throw std::invalid_argument(std::string(what) + ": the field has " +
                                std::to_string(field.rows()) + " rows for " +
                                std::to_string(model_.nodeCount()) + " nodes");
  for (int eq = 0; eq < dofs_.freeCount(); ++eq) {
    const NodeDof& d = dofs_.dofOf(eq);
    x[eq] = field(d.node, dofIndex(d.dof));
  }
  return x;
}

NodalField TransientSystem::nodalField(const Eigen::VectorXd& uFree, double t) const {
  Eigen::VectorXd u(dofs_.size());
  u.head(dofs_.freeCount()) = uFree;
  for (int eq = dofs_.freeCount(); eq < dofs_.size(); ++eq) u[eq] = supportValue(eq, t, 0);
  return toNodalField(model_, dofs_, u);
}

Eigen::VectorXd TransientSystem::initialAcceleration(const TransientState& s) const {
  Eigen::VectorXd r;
  force(s.t, r);
  r -= K_ * s.u;
  if (damped_) r -= C_ * s.v;
  return accelerationOf(M_, std::move(r), "transient analysis");
}

Eigen::VectorXd accelerationOf(const SparseMatrix& M, Eigen::VectorXd r, const char* analysis) {
  // Massless dofs: a unit diagonal and a zero right-hand side pin their acceleration at 0
  // without touching the others (their rows and columns of M are empty).
  Eigen::VectorXd colSum = Eigen::VectorXd::Zero(M.cols());
  for (int k = 0; k < M.outerSize(); ++k)
    for (SparseMatrix::InnerIterator it(M, k); it; ++it) colSum[k] += std::abs(it.value());
  SparseMatrix A = M;
  for (int eq = 0; eq < A.cols(); ++eq)
    if (colSum[eq] == 0) {
      A.coeffRef(eq, eq) = 1;
      r[eq] = 0;
    }
  SparseLU lu;
  lu.compute(A);
  if (!lu.healthy(kSingularRcond)) {
    std::ostringstream msg;
    msg << analysis << ": the mass matrix is singular (UMFPACK rcond = " << lu.rcond()
        << ") in a way that massless dofs do not explain, so the initial acceleration is "
           "undefined";
    throw SolveError(msg.str());
  }
  return lu.solve(r);
}

SupportMotion harmonicSupportMotion(int node, Dof dof, double amplitude, double omega,
                                    double phase) {
  SupportMotion m;
  m.node = node;
  m.dof = dof;
  m.displacement = [=](double t) { return amplitude * std::sin(omega * t + phase); };
  m.velocity = [=](double t) { return amplitude * omega * std::cos(omega * t + phase); };
  m.acceleration = [=](double t) {
    return -amplitude * omega * omega * std::sin(omega * t + phase);
  };
  return m;
}

}  // namespace beamrotor

#include "fem/assembly/RigidTies.hpp"

#include <complex>
#include <set>
#include <stdexcept>
#include <string>

#include "fem/assembly/ReducedSystem.hpp"
#include "fem/model/Model.hpp"

namespace beamrotor {

namespace {

/// (theta x r)_i as coefficients on theta's components: row i of the cross-product matrix.
Eigen::Matrix3d crossMatrix(const Eigen::Vector3d& r) {
  Eigen::Matrix3d m;
  m << 0, r.z(), -r.y(), -r.z(), 0, r.x(), r.y(), -r.x(), 0;
  return m;
}

}  // namespace

std::vector<TiedEquation> tiedEquations(const Model& model, const DofMap& dofs) {
  std::vector<TiedEquation> out;
  if (model.rigidTies().empty()) return out;
  const Eigen::VectorXd prescribed = prescribedValues(model, dofs);
  std::set<int> slaves, masters;
  for (const RigidTie& t : model.rigidTies()) masters.insert(t.master);
  for (const RigidTie& t : model.rigidTies()) {
    const auto fail = [&](const std::string& why) {
      throw std::invalid_argument("rigid tie '" + t.name + "': " + why);
    };
    if (t.master == t.slave) fail("a node cannot be tied to itself");
    if (masters.count(t.slave))
      fail("node " + std::to_string(t.slave) +
           " follows one node and leads another: tie every node to one master directly");
    // theta x r: the translation of a point r away from the master under its rotation.
    const Eigen::Matrix3d cross = crossMatrix(model.nodes()[t.slave] - model.nodes()[t.master]);
    for (Dof d : t.dofs) {
      const int eq = dofs.equation(t.slave, d);
      if (eq < 0) continue;  // the slave has no such dof: nothing to tie
      if (dofs.isConstrained(eq)) fail(model.describe({t.slave, d}) + " is also held by a support");
      if (!slaves.insert(eq).second) fail(model.describe({t.slave, d}) + " is tied twice");
      TiedEquation tied{eq, {}};
      const auto term = [&](Dof masterDof, double c) {
        if (c == 0) return;
        const int m = dofs.equation(t.master, masterDof);
        if (m < 0)
          fail("the master " + model.describe({t.master, masterDof}) +
               " is not a dof of the model, and the tie needs it");
        if (dofs.isConstrained(m) && prescribed[m] != 0)
          fail("the master " + model.describe({t.master, masterDof}) +
               " is prescribed a value; a tie follows only fixed or free masters");
        tied.terms.push_back({m, c});
      };
      const int i = dofIndex(d);
      term(d, 1);
      if (!isRotation(d))
        for (int k = 0; k < 3; ++k) term(kAllDofs[3 + k], cross(i, k));
      out.push_back(std::move(tied));
    }
  }
  return out;
}

SparseMatrix tieTransformation(const std::vector<TiedEquation>& tied, int freeCount) {
  std::vector<bool> isTied(freeCount, false);
  for (const TiedEquation& t : tied) isTied[t.equation] = true;
  std::vector<Eigen::Triplet<double>> entries;
  for (int i = 0; i < freeCount; ++i)
    if (!isTied[i]) entries.emplace_back(i, i, 1.0);
  for (const TiedEquation& t : tied)
    for (const TieTerm& term : t.terms)
      if (term.equation < freeCount) entries.emplace_back(t.equation, term.equation, term.coefficient);
  SparseMatrix T(freeCount, freeCount);
  T.setFromTriplets(entries.begin(), entries.end());
  return T;
}

SparseMatrix tiedStiffness(const SparseMatrix& K, const SparseMatrix& T,
                           const std::vector<TiedEquation>& tied) {
  SparseMatrix reduced = SparseMatrix(T.transpose()) * K * T;
  std::vector<Eigen::Triplet<double>> diagonal;
  for (const TiedEquation& t : tied) {
    const double k = K.coeff(t.equation, t.equation);
    diagonal.emplace_back(t.equation, t.equation, k > 0 ? k : 1.0);
  }
  SparseMatrix D(K.rows(), K.cols());
  D.setFromTriplets(diagonal.begin(), diagonal.end());
  reduced += D;
  reduced.makeCompressed();
  return reduced;
}

TieReduction::TieReduction(const Model& model, const DofMap& dofs)
    : tied_(tiedEquations(model, dofs)) {
  if (tied_.empty()) return;
  T_ = tieTransformation(tied_, dofs.freeCount());
  for (const RigidTie& t : model.rigidTies()) {
    Arm arm;
    arm.r = model.nodes()[t.slave] - model.nodes()[t.master];
    for (int k = 0; k < 3; ++k) {
      const int m = dofs.equation(t.master, kAllDofs[3 + k]);
      if (m >= 0 && !dofs.isConstrained(m)) arm.masterRotation[k] = m;
    }
    for (Dof d : t.dofs)
      if (!isRotation(d)) arm.followerTranslation[dofIndex(d)] = dofs.equation(t.slave, d);
    arms_.push_back(arm);
  }
}

std::vector<int> TieReduction::tiedNumbers() const {
  std::vector<int> out;
  for (const TiedEquation& t : tied_) out.push_back(t.equation);
  return out;
}

SparseMatrix TieReduction::stiffness(const SparseMatrix& K) const {
  return empty() ? K : tiedStiffness(K, T_, tied_);
}

SparseMatrix TieReduction::projected(const SparseMatrix& A) const {
  if (empty()) return A;
  return SparseMatrix(SparseMatrix(T_.transpose()) * A * T_);
}

SparseMatrix TieReduction::geometric(const SparseMatrix& KG,
                                     const Eigen::VectorXd& residual) const {
  if (empty()) return KG;
  std::vector<Eigen::Triplet<double>> entries;
  for (const Arm& arm : arms_) {
    Eigen::Vector3d F = Eigen::Vector3d::Zero();
    for (int k = 0; k < 3; ++k)
      if (arm.followerTranslation[k] >= 0) F[k] = -residual[arm.followerTranslation[k]];
    const Eigen::Matrix3d k = F.dot(arm.r) * Eigen::Matrix3d::Identity() -
                              0.5 * (F * arm.r.transpose() + arm.r * F.transpose());
    for (int i = 0; i < 3; ++i)
      for (int j = 0; j < 3; ++j)
        if (arm.masterRotation[i] >= 0 && arm.masterRotation[j] >= 0 && k(i, j) != 0)
          entries.emplace_back(arm.masterRotation[i], arm.masterRotation[j], k(i, j));
  }
  SparseMatrix own(KG.rows(), KG.cols());
  own.setFromTriplets(entries.begin(), entries.end());
  return SparseMatrix(projected(KG) + own);
}

Eigen::VectorXd TieReduction::loads(const Eigen::VectorXd& f) const {
  if (empty()) return f;
  return T_.transpose() * f.head(T_.rows());
}

Eigen::MatrixXd TieReduction::expand(const Eigen::MatrixXd& q) const {
  if (empty()) return q;
  return T_ * q;
}

Eigen::VectorXcd TieReduction::expand(const Eigen::VectorXcd& q) const {
  if (empty()) return q;
  return T_.cast<std::complex<double>>() * q;
}

Eigen::VectorXd stateResidual(const Model& model, const DofMap& dofs, const Eigen::VectorXd& u) {
  return elementForces(model, dofs, u) - nodalLoadVector(model, dofs);
}

void addTiedReactions(const std::vector<TiedEquation>& tied, const DofMap& dofs,
                      const Eigen::VectorXd& r, Eigen::VectorXd& out) {
  for (const TiedEquation& t : tied)
    for (const TieTerm& term : t.terms)
      if (dofs.isConstrained(term.equation))
        out[term.equation - dofs.freeCount()] += term.coefficient * r[t.equation];
}

}  // namespace beamrotor

#include "fem/assembly/RigidTies.hpp"

#include <algorithm>
#include <complex>
#include <functional>
#include <map>
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

/// A chain of ties (a follower that leads another tie) resolved: each term on a tied
/// equation replaced by that equation's own terms, times its coefficient, until every term
/// names an independent or constrained equation (the composition of the rigid motions; for
/// ties of every dof, the follower's tie to the chain's first master). Equations outside
/// chains keep their terms as they are. Throws std::invalid_argument naming a tie of a loop
/// (`names`: each tied equation's tie).
void resolveChains(std::vector<TiedEquation>& tied, const std::vector<std::string>& names) {
  std::map<int, std::size_t> indexOf;
  for (std::size_t i = 0; i < tied.size(); ++i) indexOf[tied[i].equation] = i;
  enum class State { open, resolving, resolved };
  std::vector<State> state(tied.size(), State::open);
  const std::function<void(std::size_t)> resolve = [&](std::size_t i) {
    if (state[i] == State::resolved) return;
    if (state[i] == State::resolving)
      throw std::invalid_argument("rigid tie '" + names[i] +
                                  "' closes a loop of ties: a chain of ties needs a first "
                                  "master that follows nothing");
    state[i] = State::resolving;
    bool chained = false;
    for (const TieTerm& term : tied[i].terms)
      if (const auto j = indexOf.find(term.equation); j != indexOf.end()) {
        resolve(j->second);
        chained = true;
      }
    if (chained) {
      std::map<int, double> sum;  // by equation, so that a master reached twice adds up
      for (const TieTerm& term : tied[i].terms) {
        const auto j = indexOf.find(term.equation);
        if (j == indexOf.end()) {
          sum[term.equation] += term.coefficient;
          continue;
        }
        for (const TieTerm& inner : tied[j->second].terms)
          sum[inner.equation] += term.coefficient * inner.coefficient;
      }
      tied[i].terms.clear();
      for (const auto& [equation, coefficient] : sum)
        if (coefficient != 0) tied[i].terms.push_back({equation, coefficient});
    }
    state[i] = State::resolved;
  };
  for (std::size_t i = 0; i < tied.size(); ++i) resolve(i);
}

}  // namespace

std::vector<TiedEquation> tiedEquations(const Model& model, const DofMap& dofs) {
  std::vector<TiedEquation> out;
  if (model.rigidTies().empty()) return out;
  const Eigen::VectorXd prescribed = prescribedValues(model, dofs);
  std::set<int> slaves;
  std::vector<std::string> names;  // each tied equation's tie, for messages
  for (const RigidTie& t : model.rigidTies()) {
    const auto fail = [&](const std::string& why) {
      throw std::invalid_argument("rigid tie '" + t.name + "': " + why);
    };
    if (t.master == t.slave) fail("a node cannot be tied to itself");
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
      names.push_back(t.name);
    }
  }
  resolveChains(out, names);
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
  std::map<int, const RigidTie*> tieOf;  // by follower
  for (const RigidTie& t : model.rigidTies()) tieOf[t.slave] = &t;
  for (const RigidTie& t : model.rigidTies()) {
    // In a chain, the arm reaches back to the first master the follower moves with as one
    // body: past each master that follows its own master in every dof this tie ties (the
    // loops were refused by tiedEquations).
    int master = t.master;
    for (auto up = tieOf.find(master); up != tieOf.end(); up = tieOf.find(master)) {
      const std::vector<Dof>& held = up->second->dofs;
      const bool whole = std::all_of(t.dofs.begin(), t.dofs.end(), [&](Dof d) {
        return std::find(held.begin(), held.end(), d) != held.end();
      });
      if (!whole) break;
      master = up->second->master;
    }
    Arm arm;
    arm.r = model.nodes()[t.slave] - model.nodes()[master];
    for (int k = 0; k < 3; ++k) {
      const int m = dofs.equation(master, kAllDofs[3 + k]);
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

#include "fem/assembly/RigidTies.hpp"

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

void addTiedReactions(const std::vector<TiedEquation>& tied, const DofMap& dofs,
                      const Eigen::VectorXd& r, Eigen::VectorXd& out) {
  for (const TiedEquation& t : tied)
    for (const TieTerm& term : t.terms)
      if (dofs.isConstrained(term.equation))
        out[term.equation - dofs.freeCount()] += term.coefficient * r[t.equation];
}

}  // namespace beamrotor

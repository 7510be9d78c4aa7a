#include "fem/assembly/ReducedSystem.hpp"

#include <stdexcept>

#include "fem/assembly/ParallelParts.hpp"
#include "fem/model/Model.hpp"

namespace beamrotor {

Eigen::VectorXd prescribedValues(const Model& model, const DofMap& dofs) {
  Eigen::VectorXd u = Eigen::VectorXd::Zero(dofs.size());
  for (const Support& s : model.supports())
    for (const PrescribedDof& p : s.dofs) u[dofs.equation(s.node, p.dof)] = p.value;
  return u;
}

Eigen::VectorXd reducedRightHandSide(const Model& model, const DofMap& dofs, Eigen::VectorXd f,
                                     const Eigen::VectorXd& uPrescribed) {
  // f's own storage, shortened where it lies (realloc): no second vector of its length.
  Eigen::VectorXd rhs = std::move(f);
  rhs.conservativeResize(dofs.freeCount());
  if (uPrescribed.tail(dofs.constrainedCount()).any()) {
    // K u_C computed element by element (element loads excluded: they are already in f).
    Eigen::VectorXd push = Eigen::VectorXd::Zero(dofs.size());
    for (const auto& e : model.elements()) {
      const ElementVector ue = gather(*e, dofs, uPrescribed);
      if (!ue.any()) continue;
      const ElementVector fe = e->stiffness() * ue;
      const auto d = e->dofs();
      for (int a = 0; a < int(d.size()); ++a) push[dofs.equation(d[a])] += fe[a];
    }
    rhs -= push.head(dofs.freeCount());
  }
  return rhs;
}

namespace {
/// Lays out the first `count` entries of a vector ordered by equation number per node.
NodalField layOut(const Model& model, const DofMap& dofs, const Eigen::VectorXd& v, int count) {
  NodalField field = NodalField::Zero(model.nodeCount(), kDofKinds);
  forEvenParts(count, [&](int first, int end) {
    for (int eq = first; eq < end; ++eq) {
      const NodeDof& d = dofs.dofOf(eq);
      field(d.node, dofIndex(d.dof)) = v[eq];
    }
  });
  return field;
}
}  // namespace

NodalField toNodalField(const Model& model, const DofMap& dofs, const Eigen::VectorXd& u) {
  return layOut(model, dofs, u, dofs.size());
}

Eigen::VectorXd fromNodalField(const DofMap& dofs, const NodalField& field) {
  Eigen::VectorXd u(dofs.size());
  for (int eq = 0; eq < dofs.size(); ++eq) {
    const NodeDof& d = dofs.dofOf(eq);
    u[eq] = field(d.node, dofIndex(d.dof));
  }
  return u;
}

NodalField freeToNodalField(const Model& model, const DofMap& dofs, const Eigen::VectorXd& uf) {
  return layOut(model, dofs, uf, dofs.freeCount());
}

SystemSize systemSize(const Model& model, const DofMap& dofs, long long stiffnessEntries,
                      double factorEntries) {
  return SystemSize{model.nodeCount(), int(model.elements().size()),
                    dofs.size(),       dofs.freeCount(),
                    stiffnessEntries,  factorEntries};
}

}  // namespace beamrotor

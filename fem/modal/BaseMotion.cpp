#include "fem/modal/BaseMotion.hpp"

#include <cmath>
#include <numbers>
#include <stdexcept>

#include "fem/assembly/ReducedSystem.hpp"
#include "fem/modal/HarmonicResponse.hpp"
#include "fem/modal/Modal.hpp"
#include "fem/solvers/Errors.hpp"

namespace beamrotor {

namespace {

using Complex = std::complex<double>;

/// 1 on every free dof of kind `direction`: the rigid translation along it.
Eigen::VectorXd rigidTranslation(const DofMap& dofs, int direction) {
  Eigen::VectorXd r = Eigen::VectorXd::Zero(dofs.freeCount());
  for (int eq = 0; eq < dofs.freeCount(); ++eq)
    if (dofIndex(dofs.dofOf(eq).dof) == direction) r[eq] = 1;
  return r;
}

/// A full-length complex vector (ordered as `dofs`) laid out per node.
ComplexNodalField toComplexField(const Model& model, const DofMap& dofs, const ComplexVector& u) {
  const NodalField re = toNodalField(model, dofs, u.real());
  const NodalField im = toNodalField(model, dofs, u.imag());
  ComplexNodalField out(re.rows(), kDofKinds);
  for (Eigen::Index i = 0; i < re.size(); ++i) out.data()[i] = {re.data()[i], im.data()[i]};
  return out;
}

}  // namespace

Complex BaseMotionPoint::absolute(int node, int direction) const {
  const double w = 2 * std::numbers::pi * frequencyHz;
  return relative(node, direction) - groundAcceleration / (w * w);
}

double BaseMotionPoint::transmissibility(int node, int direction) const {
  const double w = 2 * std::numbers::pi * frequencyHz;
  return std::abs(-w * w * absolute(node, direction)) / std::abs(groundAcceleration);
}

BaseMotionResult solveBaseMotion(const Model& model, const BaseMotionOptions& options) {
  BaseMotionResult result;
  result.options = options;
  const HarmonicResponse system(model, options.alpha, options.beta);
  const DofMap& dofs = system.dofs();
  const Eigen::VectorXd r = rigidTranslation(dofs, options.direction);
  const Eigen::VectorXd Mr = system.mass() * r;
  result.totalMass = r.dot(Mr);
  if (!(result.totalMass > 0))
    throw std::invalid_argument("no mass moves along the direction of the ground's motion");
  if (options.method == BaseMotionMethod::modal) {
    result.modal = solveModes(model, {options.modes, 0});
    for (const Mode& m : result.modal.modes) {
      const double wj = std::sqrt(std::max(0.0, m.eigenvalue));
      if (!(wj > 0))
        throw std::domain_error(
            "a mode of zero frequency moves with the ground as a rigid body: support the "
            "structure");
      result.modalDamping.push_back(options.modalDamping + options.alpha / (2 * wj) +
                                    options.beta * wj / 2);
    }
  }
  for (double hz : options.frequenciesHz) {
    BaseMotionPoint p;
    p.frequencyHz = hz;
    const double w = 2 * std::numbers::pi * hz;
    const double ag = options.displacement > 0 ? w * w * options.displacement : options.acceleration;
    p.groundAcceleration = ag;
    ComplexVector u;
    if (options.method == BaseMotionMethod::direct) {
      ComplexVector f = ComplexVector::Zero(dofs.size());
      f.head(dofs.freeCount()) = (-ag * Mr).cast<Complex>();
      u = system.solve(w, f);
      p.relative = toComplexField(model, dofs, u);
    } else {
      p.relative = ComplexNodalField::Zero(model.nodeCount(), kDofKinds);
      for (std::size_t j = 0; j < result.modal.modes.size(); ++j) {
        const Mode& m = result.modal.modes[j];
        const double wj = std::sqrt(m.eigenvalue), zeta = result.modalDamping[j];
        const Complex q = -m.participation[options.direction] * ag /
                          Complex(m.eigenvalue - w * w, 2 * zeta * wj * w);
        p.relative += m.shape.cast<Complex>() * q;
      }
    }
    // r' M u''_abs with u''_abs = -w^2 u + a_g r over the free dofs.
    Complex inertia = 0;
    for (int eq = 0; eq < dofs.freeCount(); ++eq) {
      if (Mr[eq] == 0) continue;
      const NodeDof& nd = dofs.dofOf(eq);
      inertia += Mr[eq] * (-w * w) * p.relative(nd.node, dofIndex(nd.dof));
    }
    p.baseForce = inertia + result.totalMass * ag;
    result.points.push_back(std::move(p));
  }
  return result;
}

}  // namespace beamrotor

#include "fem/rotor/RotorUnbalance.hpp"

#include <stdexcept>

#include "fem/rotor/DynamicStiffness.hpp"
#include "fem/solvers/RotorFactor.hpp"
#include "fem/timing/Stopwatch.hpp"

namespace beamrotor {

Eigen::VectorXcd unbalanceForces(const RotorSystem& system,
                                 const std::vector<Unbalance>& unbalance) {
  using Complex = std::complex<double>;
  // f_y = m e e^{i phase}, f_z = -i m e e^{i phase} (Re(-i e^{i(Omega t + phase)}) =
  // sin(Omega t + phase)); a couple f_rz = U_c e^{i phase}, f_ry = i U_c e^{i phase}
  // (Re(i e^{i(...)}) = -sin).
  const DofMap& dofs = system.dofs();
  const Model& model = system.model();
  Eigen::VectorXcd f = Eigen::VectorXcd::Zero(system.size());
  for (const Unbalance& u : unbalance) {
    const int y = dofs.equation(u.node, Dof::uy), z = dofs.equation(u.node, Dof::uz);
    if (!dofs.isFree(y) || !dofs.isFree(z))
      throw std::invalid_argument("an unbalance needs free uy and uz at " +
                                  model.describe({u.node, Dof::uy}));
    const Complex heavy = u.me * std::polar(1.0, u.phase);
    f[y] += heavy;
    f[z] += Complex(0, -1) * heavy;
    if (u.moment == 0) continue;
    const int ry = dofs.equation(u.node, Dof::ry), rz = dofs.equation(u.node, Dof::rz);
    if (!dofs.isFree(ry) || !dofs.isFree(rz))
      throw std::invalid_argument("a couple unbalance needs free ry and rz at " +
                                  model.describe({u.node, Dof::ry}));
    const Complex couple = u.moment * std::polar(1.0, u.phase);
    f[rz] += couple;
    f[ry] += Complex(0, 1) * couple;
  }
  return f;
}

UnbalanceResult solveUnbalance(const Model& model, const std::vector<Unbalance>& unbalance,
                               const std::vector<double>& speeds, const std::vector<int>& nodes,
                               ProportionalDamping damping) {
  using Complex = std::complex<double>;
  Stopwatch clock, total;
  UnbalanceResult result;
  result.speeds = speeds;
  result.nodes = nodes;
  result.orbits.assign(nodes.size(), {});

  // 1. Matrices, and the unit force pattern.
  const RotorSystem system(model, damping);
  const DofMap& dofs = system.dofs();
  const Eigen::VectorXcd f = unbalanceForces(system, unbalance);
  const ComplexSparseMatrix M = system.mass().cast<Complex>();
  const ComplexSparseMatrix G = system.gyroscopic().cast<Complex>();
  result.time.assembly = clock.lap();

  // 2. One complex solve per speed; every speed's matrix has the same pattern.
  RepeatedFactor<Complex> factor;
  for (double speed : speeds) {
    const ComplexSparseMatrix K = system.stiffness(speed).cast<Complex>();
    const ComplexSparseMatrix C = system.damping(speed).cast<Complex>();
    const Complex iw(0, speed);
    result.time.assembly += clock.lap();
    factorizeDynamicStiffness(factor, K - speed * speed * M + iw * (C + speed * G), speed,
                              "unbalance response", "the speed");
    result.time.factor += clock.lap();
    const Eigen::VectorXcd q = factor.solve(Eigen::VectorXcd(speed * speed * f));
    for (std::size_t k = 0; k < nodes.size(); ++k) {
      const int y = dofs.equation(nodes[k], Dof::uy), z = dofs.equation(nodes[k], Dof::uz);
      result.orbits[k].push_back({dofs.isFree(y) ? q[y] : 0.0, dofs.isFree(z) ? q[z] : 0.0});
    }
    result.time.solve += clock.lap();
  }
  result.size = system.systemSize(factor.factorEntries());
  result.symbolicAnalyses = factor.analyses();
  result.time.total = total.lap();
  return result;
}

}  // namespace beamrotor

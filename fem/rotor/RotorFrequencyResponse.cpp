#include "fem/rotor/RotorFrequencyResponse.hpp"

#include <stdexcept>

#include "fem/rotor/DynamicStiffness.hpp"
#include "fem/solvers/RotorFactor.hpp"
#include "fem/timing/Stopwatch.hpp"

namespace beamrotor {

FrequencyResponseResult solveFrequencyResponse(const Model& model, double speed, NodeDof input,
                                               NodeDof output,
                                               const std::vector<double>& frequencies,
                                               ProportionalDamping damping) {
  using Complex = std::complex<double>;
  Stopwatch clock, total;
  FrequencyResponseResult result;
  result.speed = speed;
  result.frequencies = frequencies;
  const RotorSystem system(model, damping);
  const DofMap& dofs = system.dofs();
  const int in = dofs.equation(input.node, input.dof), out = dofs.equation(output.node, output.dof);
  for (const NodeDof& d : {input, output})
    if (!dofs.isFree(dofs.equation(d.node, d.dof)))
      throw std::invalid_argument("frequency response: " + model.describe(d) +
                                  " is not a free dof");
  // K and C at the spin speed and the gyroscopic damping Omega G do not change with omega.
  const ComplexSparseMatrix K = system.stiffness(speed).cast<Complex>();
  const ComplexSparseMatrix D = (system.damping(speed) + speed * system.gyroscopic()).cast<Complex>();
  const ComplexSparseMatrix M = system.mass().cast<Complex>();
  Eigen::VectorXcd f = Eigen::VectorXcd::Zero(system.size());
  f[in] = 1;
  result.time.assembly = clock.lap();
  RepeatedFactor<Complex> factor;
  for (double w : frequencies) {
    factorizeDynamicStiffness(factor, K - w * w * M + Complex(0, w) * D, w, "frequency response",
                              "the excitation");
    result.time.factor += clock.lap();
    const Eigen::VectorXcd q = factor.solve(f);
    result.receptance.push_back(q[out]);
    result.time.solve += clock.lap();
  }
  result.size = system.systemSize(factor.factorEntries());
  result.symbolicAnalyses = factor.analyses();
  result.time.total = total.lap();
  return result;
}

}  // namespace beamrotor

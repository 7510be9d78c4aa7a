#include "fem/rotor/DynamicStiffness.hpp"

#include <sstream>
#include <utility>

#include "fem/solvers/Errors.hpp"

namespace beamrotor {

void factorizeDynamicStiffness(RepeatedFactor<std::complex<double>>& factor,
                               ComplexSparseMatrix Z, double w, const std::string& analysis,
                               const std::string& excitation) {
  if (factor.factorize(std::move(Z))) return;
  std::ostringstream msg;
  msg << analysis << ": the dynamic stiffness is singular at " << w
      << " rad/s (rcond = " << factor.rcond()
      << "): an undamped natural frequency coincides with " << excitation;
  throw SolveError(msg.str());
}

}  // namespace beamrotor

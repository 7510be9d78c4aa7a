#include "fem/model/Results.hpp"

namespace beamrotor {

double StaticResult::reaction(const std::string& support, Dof d) const {
  double sum = 0;
  for (const auto& r : reactions)
    if (r.support == support && r.dof == d) sum += r.value;
  return sum;
}

}  // namespace beamrotor

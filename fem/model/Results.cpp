#include "fem/model/Results.hpp"

namespace beamrotor {

double StaticResult::reaction(const std::string& support, Dof d) const {
  double sum = 0;
  bool found = false;
  for (const auto& r : reactions)
    if (r.support == support) {
      found = true;
      if (r.dof == d) sum += r.value;
    }
  if (found) return sum;
  for (const auto& r : elementForces)
    if (r.support == support && r.dof == d) sum += r.value;
  for (const ContactState& c : contacts)
    if (c.name == support && c.dof == d) sum += c.force;
  return sum;
}

}  // namespace beamrotor

#include "fem/model/Element.hpp"

namespace beamrotor {

ElementVector endForces(const ElementMatrix& K, const ElementVector& load, const ElementVector& u) {
  ElementVector f = K * u;
  if (load.size() > 0) f -= load;
  return f;
}

ElementVector Element::endForces(const ElementVector& u) const {
  return beamrotor::endForces(stiffness(), load(), u);
}

}  // namespace beamrotor

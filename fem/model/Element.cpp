#include "fem/model/Element.hpp"

namespace beamrotor {

ElementVector Element::endForces(const ElementVector& u) const {
  ElementVector f = stiffness() * u;
  ElementVector q = load();
  if (q.size() > 0) f -= q;
  return f;
}

}  // namespace beamrotor

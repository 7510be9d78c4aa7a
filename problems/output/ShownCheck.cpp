#include "problems/output/ShownCheck.hpp"

#include "problems/deck/ShownFieldUnit.hpp"

namespace beamrotor {

ShownCheck shownCheck(const Check& c, const OutputUnits& units) {
  const OutputUnits::Shown shown = shownField(units, checkQuantityUnit(c.quantity));
  ShownCheck s;
  s.computed = c.computed * shown.factor;
  s.reference = c.reference * shown.factor;
  s.absolute = c.reference == 0;
  const double scale = s.absolute ? shown.factor : 1;
  s.error = c.relError() * scale;
  s.tolerance = c.tolerance * scale;
  if (c.paper) s.paper = *c.paper * shown.factor;
  s.unit = shown.unit;
  return s;
}

}  // namespace beamrotor

// The units of the fields whose dimension depends on what they act on: a spring's k on its
// dof, a check's reference on its quantity. Every other field states its unit where it is read.
#pragma once

#include <string>

#include "fem/model/Dof.hpp"
#include "problems/deck/Quantity.hpp"
#include "problems/deck/parse/Units.hpp"

namespace beamrotor {

/// `translational` for ux, uy, uz; `rotational` for rx, ry, rz.
FieldUnit unitForDof(Dof d, const Dimension& translational, const Dimension& rotational);

/// The unit of a check's reference: that of the quantity it checks (N or N m for a reaction,
/// Hz for a frequency, rpm for a critical speed, ...); dimensionless for a history, whose unit
/// the deck names as free text.
FieldUnit referenceUnit(const beamrotor::Quantity& q);

}  // namespace beamrotor

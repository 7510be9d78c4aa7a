// The dimension of every numeric field of a deck, in one table keyed by the field's path with
// list indices dropped ("materials[].E" is a pressure), plus the fields whose dimension
// depends on what they act on (a spring's k on its dof, a check's reference on its quantity).
// Fields not in the table are dimensionless (counts, ratios, tolerances). FORMAT.md lists the
// same table for people.
#pragma once

#include <string>

#include "fem/model/Dof.hpp"
#include "problems/deck/Quantity.hpp"
#include "problems/deck/parse/Units.hpp"

namespace beamrotor {

/// What a numeric field holds: its dimension and the unit a bare number in it means (SI, but
/// rpm for the *_rpm fields). A field's value is returned in that unit.
struct FieldUnit {
  Dimension dimension;
  double bareSize = 1;  ///< the bare unit in SI units (2 pi / 60 for rpm)
};

/// The unit of the field at `path` ("segments[2].length"); dimensionless when not listed.
FieldUnit fieldUnitAt(const std::string& path);

/// `translational` for ux, uy, uz; `rotational` for rx, ry, rz.
FieldUnit unitForDof(Dof d, const Dimension& translational, const Dimension& rotational);

/// The unit of a check's reference: that of the quantity it checks (N or N m for a reaction,
/// Hz for a frequency, rpm for a critical speed, ...); dimensionless for a history, whose unit
/// the deck names as free text.
FieldUnit referenceUnit(const beamrotor::Quantity& q);

}  // namespace beamrotor

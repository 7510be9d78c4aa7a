// Numbers a deck field's bare unit holds (a check's computed value and reference, a
// convergence study's values: SI, or rpm for a critical speed) shown in the output units.
// Defined in OutputUnits.cpp.
#pragma once

#include <string>

#include "problems/deck/OutputUnits.hpp"

namespace beamrotor {

/// The name of a field's bare unit: its dimension's SI unit ("N m", "" when dimensionless), or
/// the unit of the table of that size ("rpm" for a *_rpm field).
std::string bareUnitName(const FieldUnit& field);

/// A number in `field`'s bare unit shown in `units`: in the user's unit where they set its
/// quantity, else in the bare unit, named (bareUnitName).
OutputUnits::Shown shownField(const OutputUnits& units, const FieldUnit& field);

/// The unit of a check of `quantity`, the text a Check keeps (" (case NAME)" after it
/// allowed): referenceUnit of the parsed quantity; dimensionless when it does not parse.
FieldUnit checkQuantityUnit(const std::string& quantity);

}  // namespace beamrotor

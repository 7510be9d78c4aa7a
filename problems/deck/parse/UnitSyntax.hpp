// How a deck writes a unit: after a number, a closing parenthesis or another unit, separated
// by spaces or not (`210 GPa`, `6000mm`, `5 kN m`, `(L/2) m`). muparser has no implicit
// product, so the multiplication is written out before parsing: `210*GPa`, `5 kN*m`. A unit
// may carry an exponent or divide (`8356 cm^4`, `12 kN/m`, `7.85 t/m^3`): those are ordinary
// operators on the unit's constant.
#pragma once

#include <functional>
#include <string>

namespace beamrotor {

/// `text` with '*' inserted before every unit written as above. `isName(word)` says whether
/// a word is a name the deck defines (a parameter hides a unit of the same name). Throws
/// std::invalid_argument when a number is followed by a word that is no unit: a misspelt unit
/// (with a did-you-mean) or a parameter hiding one.
std::string writeUnitProducts(const std::string& text,
                              const std::function<bool(const std::string&)>& isName);

/// `text` with every number literal whose value is zero written 1 (`0 m` -> `1 m`, `0.0 kN/m`
/// -> `1 kN/m`), names and the digits in them untouched: an expression with the units of a
/// zero written with a unit, whose own value, 0 in every system of units, shows no dimension.
std::string zerosAsOnes(const std::string& text);

}  // namespace beamrotor

// A unit written as a table's units line or a summary writes it, and as `output: units:` and
// `--units` take it: names from the deck's unit table (Units.hpp) multiplied by spaces and
// divided after one '/', each with an optional whole exponent: "kN m", "N s/m", "m/s^2",
// "kN m/rad", "1/s". Read without the expression machinery, so that a writer can convert a
// column's unit cheaply and on any thread.
#pragma once

#include <optional>
#include <string_view>

#include "problems/deck/parse/Units.hpp"

namespace beamrotor {

/// A unit's size in SI units and its dimension.
struct UnitSize {
  double si = 1;
  Dimension dimension;
};

/// The size of `text` as above; nullopt when a word is no unit of the table or the text does
/// not read as a product and quotient of units (an empty text is the dimensionless 1).
std::optional<UnitSize> unitSize(std::string_view text);

}  // namespace beamrotor

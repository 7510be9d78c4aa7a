// The `section NAME PROPERTY` quantity (problems/deck/Quantity.hpp): a cross-section's own
// figures, in the steel tables' names and axes (y-y the strong axis), as the summary's and
// results.json's catalogue lines print them. Any analysis of the frame gives it: it does not
// depend on the solution.
#pragma once

#include <vector>

#include "fem/model/Model.hpp"
#include "problems/deck/Deck.hpp"
#include "problems/deck/Quantity.hpp"

namespace beamrotor {

/// The section's property (SI units: m^2, m^4, m^3). A catalogue section (in `catalogue`)
/// gives every property its table prints, computed from its dimensions; any other section
/// used by an element of `model` gives A, Iy, Iz and It from its own figures (the table's Iy is
/// the member's local Iz, FORMAT.md "Cross-sections"), and Wel_y, Wel_z from the distance to
/// its outer fibres when that is known. Throws std::invalid_argument for a section no element
/// uses or a property it lacks.
double measureSection(const Quantity& q, const Model& model,
                      const std::vector<DeckCatalogSection>& catalogue);

}  // namespace beamrotor

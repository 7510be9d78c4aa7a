// Warnings for materials no engineering material resembles (issue 16): the usual cause is a
// number written in the wrong unit (`E: 210` meant as GPa is 210 Pa, and gives deflections a
// billion times too large). Warnings, not errors: a deck may model something unusual on
// purpose. The bounds, from the softest to the stiffest and lightest to heaviest solids in
// engineering use (Ashby, Materials Selection in Mechanical Design, 4th ed., ch. 4 charts):
//   E    1e6 Pa (soft elastomers) .. 1.2e12 Pa (diamond)
//   G    3e5 Pa (E / 3 of a soft elastomer) .. 6e11 Pa (diamond's 478 GPa, rounded up)
//   rho  10 kg/m^3 (aerogels, the lightest foams) .. 25000 kg/m^3 (osmium is 22600); 0 means
//        "no mass" and is not warned about
//   nu   < 0 (auxetic foams and lattices only); outside (-1, 0.5) is an error, not a warning.
#pragma once

#include <string>
#include <vector>

#include "fem/model/Section.hpp"
#include "problems/deck/parse/Field.hpp"

namespace beamrotor {

struct PlausibleRange {
  const char* key;
  double lowest, highest;
  const char* lowestExample;
  const char* highestExample;
};

/// The bounds above, for tests and documentation.
const std::vector<PlausibleRange>& plausibleMaterialRanges();

/// One line per implausible value of the deck's `materials` block (the items in the order of
/// `materials`): "deck.yaml:9:24: materials[0].E: 210 Pa is below every engineering material
/// (1e+06 Pa, soft elastomers); did you mean 210 GPa? write the unit: `E: 210 GPa`".
std::vector<std::string> materialWarnings(const Field& block, const std::vector<Material>& materials);

}  // namespace beamrotor

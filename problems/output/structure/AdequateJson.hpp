// results.json's `accuracy` object for a deck with `accuracy:` (see AdequateChoice):
//   {target, formulation, deck_formulation, elements_per_segment, elements, dofs,
//    estimated_error, mesh_error, shear_contribution (null when the deck has no Timoshenko
//    beams), seconds, search_seconds,
//    fixed_mesh {elements, dofs, seconds} (the deck's own mesh and formulation),
//    dofs_saved (fixed minus chosen), time_ratio (chosen seconds / fixed seconds)}.
#pragma once

#include "problems/output/JsonWriter.hpp"
#include "problems/run/AdequateChoice.hpp"

namespace beamrotor {

Json adequateJson(const AdequateChoice& choice);

}  // namespace beamrotor

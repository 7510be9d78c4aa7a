// The summary's lines on a frame's members: the largest displacement, and per member the
// largest |value| of each resultant (member axes), where along the member it lies, and the
// member's deflection from its chord. A frame of many members lists those of the largest
// bending moments (kSummaryMembers), the rest being in results.json and the members table.
#pragma once

#include <cstddef>
#include <ostream>
#include <string>

#include "fem/model/Model.hpp"
#include "problems/deck/Deck.hpp"
#include "problems/deck/OutputUnits.hpp"
#include "problems/output/structure/NoiseFloor.hpp"
#include "problems/output/structure/StaticExtremes.hpp"

namespace beamrotor::cli {

/// Members listed at most.
inline constexpr std::size_t kSummaryMembers = 20;

/// Nothing for a model without members (a line deck). Each line led by `indent`; values at or
/// below `floor` (the solution's round-off, NoiseFloor.hpp) shown as 0, without a place.
void printMemberExtremes(std::ostream& out, const Deck& deck, const Model& model,
                         const StaticExtremes& extremes, const NoiseFloor& floor,
                         const std::string& indent = "  ", const OutputUnits& units = {});

}  // namespace beamrotor::cli

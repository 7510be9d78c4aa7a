// The summary's lines on one static solution, the analysis' own or a load case's: reactions by
// support and displacements at the deck's named points.
#pragma once

#include <cstddef>
#include <ostream>
#include <string>
#include <vector>

#include "problems/deck/Deck.hpp"
#include "problems/deck/OutputUnits.hpp"
#include "problems/output/structure/NoiseFloor.hpp"
#include "problems/run/RunResult.hpp"

namespace beamrotor::cli {

/// Supports listed at most (a frame may have hundreds; all are in results.json).
inline constexpr std::size_t kSummarySupports = 20;

/// The points worth reporting: the deck's own, or start and end when it names none.
std::vector<const DeckPoint*> reportedPoints(const Deck& deck);

/// Unit of a displacement component: "m" or "rad".
const char* motionUnit(Dof d);

/// Numbers in the user's `units` where they set the quantity (OutputUnits.hpp); those at or
/// below `floor` (the solution's round-off, NoiseFloor.hpp) shown as 0.
///
/// Reactions by support, then the forces of the springs and bearings by name, each line led by
/// `indent`; the first kSummarySupports of each when there are more (the rest in
/// results.json).
void printReactions(std::ostream& out, const StaticResult& r, const NoiseFloor& floor,
                    const std::string& indent, const OutputUnits& units = {});

/// Displacements at the deck's reported points, each line led by `indent` (at a hinge, each
/// side's own rotation).
void printPointDisplacements(std::ostream& out, const Deck& deck, const RunResult& run,
                             const StaticResult& r, const NoiseFloor& floor,
                             const std::string& indent, const OutputUnits& units = {});

}  // namespace beamrotor::cli

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
#include "problems/output/structure/StaticExtremes.hpp"

namespace beamrotor::cli {

/// Members listed at most.
inline constexpr std::size_t kSummaryMembers = 20;

/// Whether c is a moment (T, My, Mz: N m) rather than a force (N, Vy, Vz: N).
constexpr bool isMomentComponent(ForceComponent c) {
  return c == ForceComponent::T || c == ForceComponent::My || c == ForceComponent::Mz;
}

/// Nothing for a model without members (a line deck). Each line led by `indent`.
void printMemberExtremes(std::ostream& out, const Deck& deck, const Model& model,
                         const StaticExtremes& extremes, const std::string& indent = "  ",
                         const OutputUnits& units = {});

}  // namespace beamrotor::cli

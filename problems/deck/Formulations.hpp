// The deck's names of the beam theories (`formulation:` in FORMAT.md), one table for reading
// them and for reporting the theory a run used.
#pragma once

#include <array>
#include <string>
#include <utility>

#include "elements/Beam.hpp"

namespace beamrotor {

inline constexpr std::array<std::pair<const char*, BeamTheory>, 4> kFormulations{{
    {"euler-bernoulli", BeamTheory::eulerBernoulli},
    {"timoshenko", BeamTheory::timoshenko},
    {"timoshenko-linear-full", BeamTheory::timoshenkoLinearFullIntegration},
    {"timoshenko-linear-reduced", BeamTheory::timoshenkoLinearReducedIntegration},
}};

/// The deck name of a beam theory.
inline std::string formulationName(BeamTheory theory) {
  for (const auto& [name, t] : kFormulations)
    if (t == theory) return name;
  return "?";
}

}  // namespace beamrotor

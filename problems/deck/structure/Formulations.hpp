// The deck's names of the beam theories (`formulation:` in FORMAT.md), one table for reading
// them and for reporting the theory a run used.
#pragma once

#include <array>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "elements/Beam.hpp"

namespace beamrotor {

inline constexpr std::array<std::pair<const char*, BeamTheory>, 4> kFormulations{{
    {"euler-bernoulli", BeamTheory::eulerBernoulli},
    {"timoshenko", BeamTheory::timoshenko},
    {"timoshenko-linear-full", BeamTheory::timoshenkoLinearFullIntegration},
    {"timoshenko-linear-reduced", BeamTheory::timoshenkoLinearReducedIntegration},
}};

/// Every name, in the table's order (for messages and suggestions).
inline std::vector<std::string> formulationNames() {
  std::vector<std::string> names;
  for (const auto& [name, theory] : kFormulations) names.emplace_back(name);
  return names;
}

/// The beam theory of a deck name; nullopt for a name not in the table.
inline std::optional<BeamTheory> formulationNamed(const std::string& name) {
  for (const auto& [n, theory] : kFormulations)
    if (name == n) return theory;
  return std::nullopt;
}

/// The deck name of a beam theory.
inline std::string formulationName(BeamTheory theory) {
  for (const auto& [name, t] : kFormulations)
    if (t == theory) return name;
  return "?";
}

}  // namespace beamrotor

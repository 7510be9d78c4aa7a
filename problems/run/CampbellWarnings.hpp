// Warnings of a Campbell diagram whose lines cannot be trusted everywhere (issue 42): a line
// that changes mode between two speeds even after a denser local sweep, a growing mode that
// no line follows (so the stability verdict, read on the lines, misses it), and an onset of
// instability that settles on a sweep speed (where a line jumps rather than passes through
// neutral). Each names the speeds and frequencies, and what to ask for instead. Warnings, not
// errors: the diagram is still written.
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "fem/rotor/RotorResults.hpp"
#include "fem/rotor/RotorStability.hpp"

namespace beamrotor {

/// The warnings of a Campbell diagram and of the onset found on it.
std::vector<std::string> campbellWarnings(const CampbellResult& campbell,
                                          const std::optional<InstabilityOnset>& onset);

/// One warning per mode that did not settle with whirl-dependent bearings at its own
/// eigenvalue (fem/rotor/WhirlIteration.hpp), naming its frequency and speed (`speeds`: the
/// ones the record's indices refer to).
std::vector<std::string> whirlWarnings(const WhirlCoefficientsUsed& used,
                                       const std::vector<double>& speeds);

/// The warning of an onset that settled on a sweep speed; none for another.
std::optional<std::string> onsetWarning(const std::optional<InstabilityOnset>& onset);

}  // namespace beamrotor

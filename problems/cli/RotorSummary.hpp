// The summary lines of the rotor analyses (see Summary.hpp for the others).
#pragma once

#include <optional>
#include <ostream>

#include "problems/run/RunResult.hpp"

namespace beamrotor::cli {

/// The system size a rotor analysis reports (none for rigid-body).
std::optional<SystemSize> rotorSize(const RotorOutcome& r);

/// rotor: one line per mode (damped frequency, damping, whirl); campbell: the critical
/// speeds; unbalance: the peak orbit of each response point; rigid-body: mass, centre of
/// mass, inertia and the two-dof frequencies.
void printRotor(std::ostream& out, const AnalysisOutcome& a);

}  // namespace beamrotor::cli

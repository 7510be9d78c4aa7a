// The summary lines of the rotor analyses (see Summary.hpp for the others).
#pragma once

#include <ostream>

#include "problems/deck/OutputUnits.hpp"
#include "problems/run/RunResult.hpp"

namespace beamrotor::cli {

/// The summary of a solved rotor analysis, by its kind's result (a's own). rotor: one line per
/// mode (damped frequency, damping, whirl); campbell: the critical speeds and stability;
/// unbalance: the peak orbit of each response point and the API 684 reading; rigid-body:
/// mass, centre of mass, inertia and the two-dof frequencies; frequency-response: the largest
/// receptance; critical-speed-map: its limits and the bearings' crossings; bearing-loads:
/// each bearing's load and the largest sag.
void printRotor(std::ostream& out, const AnalysisOutcome& a, const RotorModesResult& r,
                const OutputUnits& units = {});
void printRotor(std::ostream& out, const AnalysisOutcome& a, const CampbellOutcome& r,
                const OutputUnits& units = {});
void printRotor(std::ostream& out, const AnalysisOutcome& a, const UnbalanceOutcome& r,
                const OutputUnits& units = {});
void printRotor(std::ostream& out, const AnalysisOutcome& a, const RigidBodyOutcome& r,
                const OutputUnits& units = {});
void printRotor(std::ostream& out, const AnalysisOutcome& a, const FrequencyResponseOutcome& r,
                const OutputUnits& units = {});
void printRotor(std::ostream& out, const AnalysisOutcome& a, const CriticalSpeedMapOutcome& r,
                const OutputUnits& units = {});
void printRotor(std::ostream& out, const AnalysisOutcome& a, const BearingLoadsOutcome& r,
                const OutputUnits& units = {});
void printRotor(std::ostream& out, const AnalysisOutcome& a, const LevelOneOutcome& r,
                const OutputUnits& units = {});
void printRotor(std::ostream& out, const AnalysisOutcome& a, const RunUpOutcome& r,
                const OutputUnits& units = {});

}  // namespace beamrotor::cli

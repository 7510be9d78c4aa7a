// The lines `beamrotor solve` prints for a response-spectrum analysis: the spectrum and rules,
// each mode's period, Sa, participation and effective masses with the cumulative fraction of
// the mass captured, then the combined peaks (base force, reactions, largest displacement and
// member resultants).
#pragma once

#include <ostream>

#include "problems/deck/OutputUnits.hpp"
#include "problems/run/RunResult.hpp"

namespace beamrotor::cli {

/// Every number in `units` (the user's unit of its quantity where set), its unit named.
void printSpectrum(std::ostream& out, const AnalysisOutcome& a, const ResponseSpectrumResult& r,
                   const Model& model, const OutputUnits& units);

/// A base-motion analysis: the ground's motion, then per named point its largest
/// transmissibility (at which frequency) and relative displacement, and the largest base force.
void printBaseMotion(std::ostream& out, const AnalysisOutcome& a, const BaseMotionResult& r,
                     const Model& model, const OutputUnits& units);

}  // namespace beamrotor::cli

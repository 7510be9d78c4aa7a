// The human summary `beamrotor solve` prints and the check table `beamrotor check` prints.
// Reads results only; writes to a stream.
#pragma once

#include <ostream>
#include <string>
#include <vector>

#include "problems/deck/Deck.hpp"
#include "problems/deck/OutputUnits.hpp"
#include "problems/output/structure/StaticExtremes.hpp"
#include "problems/run/RunResult.hpp"

namespace beamrotor::cli {

/// Model size, reactions by support, displacements at the named points, stresses, member
/// extremes, load cases and their envelope, frequencies. The static extremes are read from
/// `extremes` (runExtremes, one per analysis: what the results directory was written from)
/// when given, else computed here.
/// Numbers are shown in the user's `units` where they set the quantity (OutputUnits.hpp).
void printRunResults(std::ostream& out, const Deck& deck, const RunResult& run,
                     const std::vector<AnalysisExtremes>* extremes = nullptr,
                     const OutputUnits& units = {});

/// One row per swept value: reactions of the first static analysis and the lowest
/// frequencies of the first modal one.
void printSweepResults(std::ostream& out, const Deck& deck, const SweepResult& sweep,
                       const OutputUnits& units = {});

/// Every check of every run with its relative error and PASS / FAIL, and those whose `when:`
/// is false as n/a. `label(i)` names run i in a sweep (empty for a single run). Returns the
/// number of failed checks. Values and references are shown with their unit, the user's where
/// they set its quantity (shownField); against a zero reference the error and the
/// tolerance are absolute and shown in that unit too.
int printChecks(std::ostream& out, const Deck& deck, const std::vector<const RunResult*>& runs,
                const std::vector<std::string>& labels, const OutputUnits& units = {});

/// s followed by spaces up to `width` characters (at least one space).
std::string padded(const std::string& s, std::size_t width);

/// "3.14159", "2.5e+11": six significant digits.
std::string formatValue(double v);

/// "12.3 kN m": `value`, held in `unit`, in the user's unit of its quantity where they set it,
/// else as the summary shows it on its own (`own`: {1e-6, "MPa"} for a stress in Pa).
std::string valueText(double value, const std::string& unit, const OutputUnits& units,
                      const OutputUnits::Shown& own);
/// The same, the summary's own unit being `unit` itself.
std::string valueText(double value, const std::string& unit, const OutputUnits& units);

}  // namespace beamrotor::cli

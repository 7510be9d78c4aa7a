// The human summary `beamrotor solve` prints and the check table `beamrotor check` prints.
// Reads results only; writes to a stream.
#pragma once

#include <ostream>
#include <string>
#include <vector>

#include "problems/deck/Deck.hpp"
#include "problems/run/RunResult.hpp"

namespace beamrotor::cli {

/// Model size, reactions by support, displacements at the named points, frequencies.
void printRunResults(std::ostream& out, const Deck& deck, const RunResult& run);

/// One row per swept value: reactions of the first static analysis and the lowest
/// frequencies of the first modal one.
void printSweepResults(std::ostream& out, const Deck& deck, const SweepResult& sweep);

/// Every check of every run with its relative error and PASS / FAIL, and those whose `when:`
/// is false as n/a. `label(i)` names run i in a sweep (empty for a single run). Returns the
/// number of failed checks.
int printChecks(std::ostream& out, const Deck& deck, const std::vector<const RunResult*>& runs,
                const std::vector<std::string>& labels);

/// s followed by spaces up to `width` characters (at least one space).
std::string padded(const std::string& s, std::size_t width);

/// "3.14159", "2.5e+11": six significant digits.
std::string formatValue(double v);

}  // namespace beamrotor::cli

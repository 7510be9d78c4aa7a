// Whether a static solve's mesh is past the point where round-off outweighs discretisation
// error (issue 7): a warning for the summary and results.json, never an error.
#pragma once

#include <optional>
#include <string>

#include "fem/model/Model.hpp"
#include "fem/model/Results.hpp"

namespace beamrotor {

/// The warning, or nullopt when the mesh is fine. The rule compares two errors, both relative
/// and independent of the model's units:
/// - round-off: measured on the solution itself (StaticResult::roundOff, an upper estimate:
///   the solver's error from the residual in extended precision and one correction solve,
///   plus the response to the rounding of K's own entries; Higham, Accuracy and Stability of
///   Numerical Algorithms, ch. 7 and 12);
/// - discretisation: the Hermite beam element's nodal error under loads it does not represent
///   exactly is at most about (h / L)^2 / 3 (a uniform load lumped to the nodes: exactly
///   1 / (3 N^2) at a cantilever's tip, see problems/verify/OverRefinement.cpp), h the smallest
///   line element and L the total length of line elements.
/// Round-off above that bound means refining has stopped helping.
std::optional<std::string> overRefinementWarning(const Model& model, const StaticResult& r);

}  // namespace beamrotor

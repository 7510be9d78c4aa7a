// Whether a static solve's mesh is past the point where round-off outweighs discretisation
// error (issue 7): a warning for the summary and results.json, never an error.
#pragma once

#include <optional>
#include <string>

#include "fem/model/Model.hpp"
#include "fem/model/Results.hpp"

namespace beamrotor {

/// The warning, or nullopt when the mesh is fine. The rule compares two estimates:
/// - round-off: a backward-stable factorisation leaves a relative error of about
///   eps / rcond (Higham, Accuracy and Stability of Numerical Algorithms, 7.1), rcond being
///   the solver's reciprocal condition estimate;
/// - discretisation: the Hermite beam element's nodal error under loads it does not represent
///   exactly is at most about (h / L)^2 / 3 (a uniform load lumped to the nodes: exactly
///   1 / (3 N^2) at a cantilever's tip, see problems/verify/OverRefinement.cpp), h the smallest
///   line element and L the total length of line elements.
/// Round-off above that bound means refining has stopped helping: on the verification
/// cantilever it fires from about 400 elements, where the measured error stops falling.
std::optional<std::string> overRefinementWarning(const Model& model, const StaticResult& r);

}  // namespace beamrotor

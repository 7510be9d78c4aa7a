// Whether a static solution moves further than the structure is large (issue 16): linear
// statics assumes small displacements, so such a result is wrong whatever its cause, usually
// a number in the wrong unit (E in GPa written as a bare 210). A warning for the summary and
// results.json, never an error.
#pragma once

#include <optional>
#include <string>

#include "fem/model/Model.hpp"
#include "fem/model/Results.hpp"

namespace beamrotor {

/// The warning when the largest nodal translation (Euclidean norm of ux, uy, uz) exceeds the
/// structure's size, the largest extent of its nodes along x, y or z; nullopt otherwise and
/// for a model whose nodes all sit at one place (bodies on springs have no size to compare).
std::optional<std::string> displacementWarning(const Model& model, const StaticResult& r);

}  // namespace beamrotor

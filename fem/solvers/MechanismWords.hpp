// A mechanism (SupportCheck.hpp) in words: which parts of the structure move and how
// (translate along an axis, turn about a point, move as a free body), and which hinges let
// them, so that a user sees what to hold instead of a list of dofs.
#pragma once

#include <string>

#include "fem/model/DofMap.hpp"

namespace beamrotor {

class Model;
struct Mechanism;

/// "the structure is not fully supported: ... Add a support or a spring that holds it." The
/// line elements are grouped into parts that move as one rigid body in every mode (a part ends
/// where the motion changes, i.e. at a hinge); each moving part's motions over the modes are
/// named, then the hinges at the parts' ends, then moving dofs off the line.
std::string describeMechanism(const Model& model, const DofMap& dofs, const Mechanism& mechanism);

}  // namespace beamrotor

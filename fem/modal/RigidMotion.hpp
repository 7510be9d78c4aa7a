// How much of a mode or buckling shape is each rigid motion of the structure: the direction of
// its effective mass, which names a frame's modes as an engineer reads them (sway, torsion).
#pragma once

#include <array>
#include <string>
#include <vector>

#include "fem/assembly/Assembly.hpp"
#include "fem/model/DofMap.hpp"
#include "fem/model/Model.hpp"
#include "fem/model/Results.hpp"

namespace beamrotor {

/// Shares of a shape along the six rigid motions: translations along x, y, z, then rotations
/// about the axes x, y, z through the centre of mass (each rotation's part that is no
/// translation, so the axis' place does not matter). With r_k a rigid motion over the free
/// dofs and M a mass matrix, share_k = (r_k' M phi)^2 / ((r_k' M r_k)(phi' M phi)): the
/// effective mass of motion k over its total, in [0, 1]; 0 for a motion no free dof carries.
using RigidShares = std::array<double, 6>;

/// The shares of each column of `shapes` (free dofs, ordered as `dofs`) under the free-free
/// mass matrix M.
std::vector<RigidShares> rigidMotionShares(const Model& model, const DofMap& dofs,
                                           const SparseMatrix& M, const Eigen::MatrixXd& shapes);

/// The same for a shape without a mass matrix (a buckling shape, nodal): a unit mass on every
/// free translation.
RigidShares rigidMotionShares(const Model& model, const NodalField& shape);

/// The rigid motion a shape is mostly, as "sway ux, 94 % of the mass" (`of`: "mass"), global y
/// being vertical (self-weight acts along -y): sway ux / sway uz, vertical uy, torsion about
/// y, rocking about x / z. Below 5 % along every motion: "local (...)".
std::string describeRigidMotion(const RigidShares& shares, const std::string& of);

}  // namespace beamrotor

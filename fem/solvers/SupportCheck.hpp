// Detecting an insufficiently supported structure (a mechanism, a free-free body, a node whose
// rotation nothing resists) on the element level, and naming it.
#pragma once

#include <string>
#include <vector>

#include "fem/assembly/Assembly.hpp"
#include "fem/model/Dof.hpp"

namespace beamrotor {

class Model;

/// The motions of the free dofs that strain no element: each element moves only as its own
/// stiffness allows without energy (rigidly, about its releases), supports and held dofs stay
/// put. They are the null space of B, the elements' strain factors stacked (K_e = B_e' B_e
/// from each element's eigenvalues, scaled by diag(K)^-1/2), found by a rank-revealing sparse
/// QR (SuiteSparseQR). B's conditioning is the square root of K's, so a fine but held mesh is
/// told apart from a mechanism far beyond where K's own pivots or energies could (a clamped
/// cantilever of 10^6 elements has cond(K) ~ 10^24 but cond(B) ~ 10^12).
struct Mechanism {
  int count = 0;                       ///< independent zero-energy motions (0: none)
  std::vector<Eigen::VectorXd> modes;  ///< a basis of them (free-length), at most 12
  std::vector<NodeDof> moving;         ///< the dofs that move in them
};

/// The mechanism of the free-free stiffness block Kff (its diagonal scales B) with the free
/// equations `held` held at their values (active contacts).
Mechanism findMechanism(const Model& model, const DofMap& dofs, const SparseMatrix& Kff,
                        const std::vector<int>& held = {});

/// Throws UnsupportedStructure naming the mechanism in words (describeMechanism), with advice.
void throwUnsupported(const Model& model, const DofMap& dofs, const Mechanism& mechanism,
                      const std::string& context);

}  // namespace beamrotor

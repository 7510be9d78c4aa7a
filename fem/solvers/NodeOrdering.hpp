// A fill-reducing order for a sparse factorisation, found on the graph of nodes rather than of
// equations. A beam model's equations come in groups of up to six per node, and every equation
// of a node couples with the equations of the same neighbouring nodes, so the graph of
// equations is the graph of nodes with each vertex repeated. Minimum degree (AMD, Amestoy,
// Davis and Duff 1996) merges only equations whose neighbours are identical, which the
// equations of one node are not once K's exact zeros are dropped (a member along x couples
// torsion only with torsion, bending only with bending), so on equations it orders up to six
// times the vertices, one by one. On nodes it orders a sixth of them and eliminates a node's
// equations together, which is what a good order does anyway. On the 3D grillage of the bench
// (10^6 equations) the order and analysis take a quarter to a half of the time, and the
// factorisation a fifth fewer operations (see README, issue 21).
#pragma once

#include <span>
#include <vector>

#include "fem/assembly/Assembly.hpp"

namespace beamrotor {

/// P such that row k of P A P' is row P[k] of A, for a structurally symmetric A (either or both
/// triangles stored). `nodeOfRow` names each row's node; the rows of a node must be
/// consecutive (as DofMap numbers the free equations) and keep their order within it.
/// Minimum degree (SuiteSparse's AMD) runs on the graph of the runs of equal nodes.
std::vector<int> nodeByNodeOrdering(const SparseMatrix& A, std::span<const int> nodeOfRow);

}  // namespace beamrotor

// Assembly straight into band storage, for a model whose free equations, numbered node by
// node, couple only near the diagonal (a line of beams, a shaft, a rod string). No pattern is
// built and no entry is searched for: entry (i, j) has its place by arithmetic.
#pragma once

#include <optional>

#include "fem/assembly/Assembly.hpp"
#include "fem/assembly/SymmetricBand.hpp"

namespace beamrotor {

/// The half-bandwidth to store the free-free block of K in when a band suits it, else none.
/// A band suits when every element's stiffness is symmetric and the band holds no more
/// entries, n (kd + 1), than the elements' matrices hold in their lower triangles (free dofs):
/// then it costs no more memory than the sparse pattern with its indices, and its Cholesky
/// factor no more than the sparse factor's fill. kd is the widest distance between two free
/// equations of one element. A line of beams (kd = 5 planar, 11 in 3D) passes; a spring
/// between far nodes, or a frame's loops, make the band too wide, and the sparse path serves.
std::optional<int> stiffnessBand(const Model& model, const DofMap& dofs);

/// The free-free block of one global matrix of a symmetric kind (stiffness, mass), in a band
/// of the given half-bandwidth (stiffnessBand's). Each part adds into its own range of
/// columns, element by element in the model's order: the entries are those of
/// SparseAssembler to the last bit, on any number of cores.
SymmetricBand assembleBand(const Model& model, const DofMap& dofs, MatrixKind kind,
                           int halfBandwidth);

}  // namespace beamrotor

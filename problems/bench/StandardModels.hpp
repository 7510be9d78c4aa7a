// The standard benchmark models, built the same way every time so figures compare run to run.
#pragma once

#include <memory>
#include <vector>

#include "fem/model/Model.hpp"

namespace beamrotor {

/// A long continuous planar Euler-Bernoulli beam: steel (E = 210e9, rho = 7850), 20 mm square
/// section, spans of 0.6 m with 10 elements each, pinned (ux = uy = 0) at every span end,
/// uniform load 1000 N/m downwards. `elements` is rounded up to whole spans.
struct PlanarBenchModel {
  std::unique_ptr<Model> model;
  int spans = 0;
  int midspanNode = -1;      ///< midspan of the middle span
  double exactMidspanW = 0;  ///< q s^4 / (384 E I), downwards negative (m)
  double exactLowestHz = 0;  ///< simply supported span: pi / (2 s^2) sqrt(E I / (rho A))
};
PlanarBenchModel planarBenchModel(int elements);

/// A square grillage of n x n bays of 1 m in the x-y plane: 3D frame elements (6 dofs per
/// node), 4 per bay edge, steel tube 60 x 4 mm, every boundary node pinned (ux = uy = uz = 0,
/// rotations free), 1000 N downwards (-z) at every node. Nodes lie on a lattice of
/// (4n + 1) x (4n + 1) points of pitch 0.25 m (only those on a grid line exist), numbered
/// row by row so the matrix stays banded.
struct GridBenchModel {
  std::unique_ptr<Model> model;
  int bays = 0;
  int side = 0;              ///< lattice points per side, 4 bays + 1
  std::vector<int> lattice;  ///< node at lattice point (i, j) = lattice[j * side + i], or -1
  double totalLoad = 0;      ///< N, the sum of the nodal loads (downwards)

  int nodeAt(int i, int j) const { return lattice[std::size_t(j) * side + i]; }
};
GridBenchModel gridBenchModel(int bays);
/// Free dofs of the n-bay grillage: 6 per node less 3 per boundary node = 42 n^2 + 6.
long long gridFreeDofs(int bays);
/// Elements of the n-bay grillage: 4 per bay edge, 2 n (n + 1) edges.
long long gridElements(int bays);
/// The bay count whose size (count(n), increasing in n) is closest to target.
int closestSize(long long target, long long (*count)(int));

/// A uniform steel shaft (1.5 m, 50 mm) with three thin disks (20 kg, at the quarter points)
/// on two isotropic bearings (1e7 N/m) at its ends; Timoshenko elements with rotary inertia,
/// lateral dofs (uy, uz, ry, rz) and gyroscopic terms; self weight along -y. `elements` is
/// rounded up to a multiple of 4 (the disks sit on nodes).
struct RotorBenchModel {
  std::unique_ptr<Model> model;
  int elements = 0;
  std::vector<int> bearingNodes;
  double bearingStiffness = 0;  ///< N/m, both directions
  double weight = 0;            ///< N, shaft and disks
};
RotorBenchModel rotorBenchModel(int elements);
/// The same shaft, disks and bearings as a planar model (ux, uy, rz; ux held at every node,
/// bearings as grounded springs on uy): at rest, the rotor's lateral modes are this model's
/// modes, each twice (one per plane).
std::unique_ptr<Model> rotorPlanarTwin(int elements);

}  // namespace beamrotor

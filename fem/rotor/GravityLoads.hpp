// Static loads of a rotor's bearings under its own weight and its disks' weights, and the
// shaft's sag. The weight is the consistent load f = M a, a the uniform acceleration g on
// every translation: for a beam element under its own weight this is exactly the consistent
// load of a uniform line load (the rigid translation is in the element's interpolation), and
// for a point mass its weight m g. Then K u = f with the bearings either as pinned supports
// (uy = uz = 0 at their nodes: what the shaft alone decides; exact for two bearings, where the
// loads are statically determinate) or as their own stiffness at a given speed (three or more
// bearings: the bearings' stiffness shares the load).
#pragma once

#include <Eigen/Dense>
#include <cmath>
#include <vector>

#include "fem/model/Model.hpp"

namespace beamrotor {

enum class BearingSupport {
  rigid,    ///< pinned at every bearing node
  elastic,  ///< the bearings' stiffness matrices at the given speed
};

/// The force a bearing exerts on the shaft (N, global y and z): the bearing carries its
/// opposite.
struct BearingForce {
  int element = -1;  ///< index into model.elements() (a bearing)
  int node = -1;
  double x = 0;  ///< the node's station (m)
  double fy = 0, fz = 0;
};

struct GravityLoads {
  std::vector<BearingForce> bearings;  ///< one per Bearing element, model order
  /// The weight on the free dofs (N, global): the sum of f's translations, which the
  /// bearings (and any supports of the model) carry.
  Eigen::Vector3d weight = Eigen::Vector3d::Zero();
  /// Deflection of every node that carries uy and uz (m): nodes[i] at x[i].
  std::vector<int> nodes;
  std::vector<double> x, uy, uz;
  /// Index of the node with the largest sag sqrt(uy^2 + uz^2) (-1 without nodes).
  int largestSag() const;
};

/// gravity: the acceleration (m/s^2, global), e.g. (0, -9.81, 0). Throws
/// std::invalid_argument without bearings, SolveError when the supported rotor can still move
/// (one bearing, no supports).
GravityLoads solveGravityLoads(const Model& model, const Eigen::Vector3d& gravity,
                               BearingSupport support, double speed = 0);

}  // namespace beamrotor

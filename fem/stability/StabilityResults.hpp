// Results of the analyses with geometric stiffness: linear buckling and second-order statics,
// as plain values.
#pragma once

#include <limits>
#include <string>
#include <vector>

#include "fem/model/Results.hpp"

namespace beamrotor {

/// One buckling mode: the load factor lambda that brings the reference load to its critical
/// value (negative: the load reversed) and its shape.
struct BucklingMode {
  double factor = 0;
  /// Scaled so that its largest translation is 1 (a twist mode without translation: its
  /// largest rotation), that entry positive.
  NodalField shape;
};

struct BucklingResult {
  StaticResult reference;              ///< the first-order state whose axial forces load KG
  std::vector<BucklingMode> modes;     ///< positive factors, ascending
  std::vector<BucklingMode> reversed;  ///< negative factors, least magnitude first (if asked)
  SystemSize size;
  SolveTimings time;
  std::vector<std::string> warnings;
};

/// Statics about the deformed state: (K + KG(N(u))) u = f, the axial forces N taken from the
/// solution itself, iterated to convergence.
struct SecondOrderResult {
  StaticResult firstOrder;   ///< K u = f
  StaticResult secondOrder;  ///< reactions from (K + KG) u - f: equilibrium in the deformed state
  int iterations = 0;        ///< linear solves after the first-order one
  /// The lowest positive buckling factor of the first-order state (infinity when nothing is
  /// compressed): the load is that many times below the critical one.
  double criticalFactor = std::numeric_limits<double>::infinity();
  /// Largest translation magnitude |(ux, uy, uz)| (and rotation magnitude) of the
  /// second-order state over the first-order one: translations anywhere along the beams and at
  /// the nodes, as `displacement max` measures them (largestDisplacement), rotations at the
  /// nodes.
  double displacementAmplification = 1, rotationAmplification = 1;
  /// The first-order state's largest translation magnitude (m) and rotation magnitude (rad),
  /// the denominators of the two ratios above.
  double firstOrderTranslation = 0, firstOrderRotation = 0;
  /// Largest bending moment (and outer-fibre normal stress, axial stress included) along the
  /// beams, exact between nodes, of the second-order state over the first-order one; 1 when
  /// the first-order value is zero.
  double momentAmplification = 1, stressAmplification = 1;
};

}  // namespace beamrotor

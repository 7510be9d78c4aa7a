// A canonical basis for repeated eigenvalues of a rotor. An axisymmetric rotor on isotropic
// bearings has every lateral mode twice at rest (the two bending planes), and its bounce modes
// stay double at any speed (a translation feels no gyroscopic moment). Any basis of such an
// eigenspace is a correct answer, and the one an eigensolver returns depends on its start
// vector; here it is replaced by a basis fixed by the physics:
//   1. whirl: the vectors that diagonalise the whirl form W(q) = sum over nodes of
//      |uy + i uz|^2 - |uy - i uz|^2 (forward minus backward orbit radii squared, times 4)
//      inside the eigenspace, ordered from the most backward to the most forward. For the
//      two planes of an isotropic rotor these are the circular backward and forward orbits,
//      the limits of the gyroscopically split modes as the speed falls to zero, so a Campbell
//      diagram's tracking (MAC) continues from rest without a jump;
//   2. when W does not separate them (all equal), the plane form |uy|^2 - |uz|^2, the y plane
//      first.
#pragma once

#include <Eigen/Dense>
#include <complex>
#include <vector>

#include "fem/model/DofMap.hpp"

namespace beamrotor {

/// Eigenvalues closer than this, relative to their size, are one repeated eigenvalue. The
/// eigensolver returns a double eigenvalue's two copies within ~1e-12 of each other; bearings
/// that differ by 1e-8 relative split a pair by less, and the vectors mixed then have a
/// residual of that order, far below any engineering accuracy.
inline constexpr double kRepeatedEigenvalue = 1e-8;

/// Replaces the columns of `vectors` (free dofs, one per eigenvalue in `lambda`, Im lambda > 0)
/// of each group of repeated eigenvalues by the canonical basis above, in its order; the
/// eigenvalues keep their places. Real eigenvalues and single ones are left alone.
void canonicalRepeatedModes(const std::vector<std::complex<double>>& lambda,
                            Eigen::MatrixXcd& vectors, const DofMap& dofs, int nodeCount);

}  // namespace beamrotor

// Shift-invert on a free-free beam: K is singular (two rigid-body modes in the plane), so the
// shift sigma = 0 cannot be factorised and the modal solver must say so; any negative shift
// works. The study measures the elastic frequencies' error and the rigid-body eigenvalues
// against the shift.
#pragma once

#include <string>
#include <vector>

namespace beamrotor::verify {

struct ShiftPoint {
  double shiftRatio = 0;    ///< -sigma / lambda_1 (lambda_1: first elastic eigenvalue, exact)
  double elasticError = 0;  ///< relative error of the first elastic frequency (beta L = 4.730041)
  double rigidBody = 0;     ///< largest |lambda| of the two rigid-body modes / lambda_1
};

struct ShiftStudy {
  std::string zeroShiftError;  ///< what the solver says at sigma = 0 (empty: it did not fail)
  std::vector<ShiftPoint> points;
};

/// A 1.5 m steel 40 x 40 mm free-free beam, 40 elements, bending in x-y only.
ShiftStudy freeFreeShiftStudy(const std::vector<double>& shiftRatios);

}  // namespace beamrotor::verify

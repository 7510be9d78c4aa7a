// A check's figures as a reader sees them, in the output units chosen (OutputUnits.hpp):
// what `beamrotor check` prints and Python's check() returns. Against a zero reference the
// error and the tolerance are absolute, in the check's unit; otherwise relative.
#pragma once

#include <optional>
#include <string>

#include "problems/deck/OutputUnits.hpp"
#include "problems/run/RunResult.hpp"

namespace beamrotor {

struct ShownCheck {
  double computed = 0, reference = 0;
  double error = 0;      ///< relative, or absolute in `unit` when `absolute`
  double tolerance = 0;  ///< likewise
  bool absolute = false;  ///< the reference is 0
  std::optional<double> paper;  ///< `paper:` in `unit`
  std::string unit;             ///< "" when dimensionless
};

/// `c` in `units`: in the user's unit of its quantity where set, else in the check's own.
ShownCheck shownCheck(const Check& c, const OutputUnits& units);

}  // namespace beamrotor

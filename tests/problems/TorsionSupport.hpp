// What the torsion suites share: an analysis' outcome by name, and Holzer's method.
#pragma once

#include <doctest/doctest.h>

#include <string>
#include <vector>

#include "problems/run/RunResult.hpp"

namespace beamrotor::test {

inline const TorsionOutcome& torsionOf(const RunResult& run, const std::string& name) {
  for (const AnalysisOutcome& a : run.analyses)
    if (a.name == name) {
      const auto* t = resultOf<TorsionOutcome>(a);
      REQUIRE(t != nullptr);
      return *t;
    }
  FAIL("no analysis " << name);
  throw;
}

/// Holzer's residual torque at omega for disks J on springs k (k[i] between disk i and i + 1),
/// free at both ends: unit twist at disk 0, the torque carried along the chain; the residual
/// (the torque past the last disk) vanishes at a natural frequency.
inline double holzerResidual(const std::vector<double>& J, const std::vector<double>& k,
                             double omega) {
  double twist = 1, torque = 0;
  for (std::size_t i = 0; i < J.size(); ++i) {
    torque += J[i] * omega * omega * twist;
    if (i < k.size()) twist -= torque / k[i];
  }
  return torque;
}

}  // namespace beamrotor::test

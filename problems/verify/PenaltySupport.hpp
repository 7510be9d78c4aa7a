// Penalty against elimination: a cantilever built of two halves joined at midspan by stiff
// springs (a penalty connection, k in ux and uy, k L^2 in rz) instead of one shared node (exact
// elimination). Soft springs leave a modelling error 3.75 E I / (k L^3) on the tip deflection;
// stiff ones make K ill-conditioned, and round-off takes over.
#pragma once

#include <vector>

namespace beamrotor::verify {

struct PenaltyPoint {
  double stiffnessRatio = 0;  ///< k / (E I / L^3); 0 for the shared node
  double error = 0;           ///< relative error of the tip deflection against P L^3 / (3 E I)
  double modelling = 0;       ///< the spring's own compliance, 3.75 / ratio (0 when shared)
  double rcond = 0;           ///< CHOLMOD's reciprocal condition estimate
};

/// One point per stiffness ratio.
std::vector<PenaltyPoint> penaltyStudy(const std::vector<double>& stiffnessRatios);
/// The same cantilever as one line: the joint is a shared node (the constraint eliminated).
PenaltyPoint eliminatedJoint();

}  // namespace beamrotor::verify

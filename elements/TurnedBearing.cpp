#include "elements/TurnedBearing.hpp"

#include <Eigen/Dense>
#include <cmath>

namespace beamrotor {

BearingCoefficients turnedCoefficients(const BearingCoefficients& k, double angle) {
  if (angle == 0) return k;  // bit for bit
  Eigen::Matrix2d T;
  T << std::cos(angle), -std::sin(angle), std::sin(angle), std::cos(angle);
  Eigen::Matrix2d K, C;
  K << k.kyy, k.kyz, k.kzy, k.kzz;
  C << k.cyy, k.cyz, k.czy, k.czz;
  const Eigen::Matrix2d Kt = T * K * T.transpose(), Ct = T * C * T.transpose();
  return {Kt(0, 0), Kt(0, 1), Kt(1, 0), Kt(1, 1), Ct(0, 0), Ct(0, 1), Ct(1, 0), Ct(1, 1)};
}

}  // namespace beamrotor

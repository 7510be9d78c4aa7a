// Combining the peaks of modal responses into the peak of the total, and combining the peaks
// of several directions of excitation.
#pragma once

#include <Eigen/Dense>
#include <vector>

namespace beamrotor {

enum class ModalRule { srss, cqc };
enum class DirectionalRule { percent30, srss };

/// Der Kiureghian's (1981) correlation of two modes' responses to white noise, for the same
/// damping ratio xi in both: with r = wj / wi,
///   rho = 8 xi^2 (1 + r) r^1.5 / ((1 - r^2)^2 + 4 xi^2 r (1 + r)^2);
/// 1 for equal frequencies, falling as they part.
double cqcCorrelation(double wi, double wj, double dampingRatio);

/// The correlations of all pairs of modes of circular frequencies `omega`: the identity for
/// SRSS, Der Kiureghian's coefficients for CQC.
Eigen::MatrixXd modalCorrelations(const std::vector<double>& omega, double dampingRatio,
                                  ModalRule rule);

/// Each row's combined peak sqrt(q' rho q), q the row of `modal` (one column per mode):
/// SRSS for rho the identity, CQC for Der Kiureghian's.
Eigen::VectorXd combineModes(const Eigen::MatrixXd& modal, const Eigen::MatrixXd& rho);

/// The combinations `rule` takes of `count` directions, as a factor per direction: for
/// `percent30` one per direction, that direction at 1 and the others at 0.3 (EN 1998-1
/// (4.19)-(4.20), and (4.20)-(4.22) of 4.3.3.5.2 with the vertical); for `srss` the one root
/// of the sum of squares (its factors all 1).
std::vector<std::vector<double>> directionalFactors(std::size_t count, DirectionalRule rule);

/// One combination's value of each row of `perDirection` (one column per direction): the
/// factored sum for `percent30`, the root of the sum of the squared factored peaks for `srss`.
Eigen::VectorXd combineDirectionsAs(const Eigen::MatrixXd& perDirection,
                                    const std::vector<double>& factors, DirectionalRule rule);

/// The peaks of several directions of excitation (one column each) combined: `percent30` the
/// largest of each direction at 100 % with the others at 30 % (EN 1998-1 (4.19)-(4.21)),
/// `srss` the square root of the sum of squares (EN 1998-1 (4.18)).
Eigen::VectorXd combineDirections(const Eigen::MatrixXd& perDirection, DirectionalRule rule);

}  // namespace beamrotor

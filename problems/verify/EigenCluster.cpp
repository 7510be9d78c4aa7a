#include "problems/verify/EigenCluster.hpp"

#include <Eigen/Dense>
#include <algorithm>
#include <cmath>
#include <numbers>

#include "fem/modal/Modal.hpp"
#include "problems/verify/VerifyModels.hpp"

namespace beamrotor::verify {

namespace {

constexpr double kClusterBeamLength = 2.0;

/// Orthonormal basis of the columns of A (thin QR).
Eigen::MatrixXd orthonormal(const Eigen::MatrixXd& A) {
  Eigen::HouseholderQR<Eigen::MatrixXd> qr(A);
  return qr.householderQ() * Eigen::MatrixXd::Identity(A.rows(), A.cols());
}

/// Largest principal angle between the column spans of A and B (same dimension): its sine is
/// the 2-norm of (I - Qa Qa^T) Qb (Bjorck and Golub 1973), accurate for small angles where the
/// cosine form is not.
double largestPrincipalAngle(const Eigen::MatrixXd& A, const Eigen::MatrixXd& B) {
  const Eigen::MatrixXd Qa = orthonormal(A), Qb = orthonormal(B);
  const Eigen::MatrixXd residual = Qb - Qa * (Qa.transpose() * Qb);
  const double sine = Eigen::JacobiSVD<Eigen::MatrixXd>(residual).singularValues()(0);
  return std::asin(std::min(sine, 1.0));
}

}  // namespace

std::vector<ClusterPoint> eigenClusterStudy(int pairs) {
  // 1. The beam: pinned in both planes at each end, axial and torsion held at the left.
  Model model;
  LineSpec spec;
  spec.dofs = DofSet::frame3d();
  spec.segments.push_back({kClusterBeamLength, steelRectangle(0.04, 0.04), 60, 0, {}});
  spec.points = {{"start", 0}, {"end", kClusterBeamLength}};
  const Line line = buildLine(model, spec);
  model.addSupport(
      {"left", line.nodes.front(), {{Dof::ux, 0}, {Dof::uy, 0}, {Dof::uz, 0}, {Dof::rx, 0}}});
  model.addSupport({"right", line.nodes.back(), {{Dof::uy, 0}, {Dof::uz, 0}}});
  const ModalResult r = solveModes(model, {2 * pairs + 2, 0});
  std::vector<const Mode*> bending;
  for (const Mode& m : r.modes)
    if (m.description.rfind("bending", 0) == 0) bending.push_back(&m);

  // 2. Per pair, the translations uy, uz at the nodes: computed vectors against the exact
  // shapes sin(n pi x / L) in each plane (Euler-Bernoulli, pinned-pinned).
  const Eigen::Index nodes = Eigen::Index(line.nodes.size());
  std::vector<ClusterPoint> points;
  for (int n = 1; n <= pairs && std::size_t(2 * n) <= bending.size(); ++n) {
    Eigen::MatrixXd computed(2 * nodes, 2), exact = Eigen::MatrixXd::Zero(2 * nodes, 2);
    for (Eigen::Index i = 0; i < nodes; ++i) {
      const int node = line.nodes[std::size_t(i)];
      for (int k = 0; k < 2; ++k) {
        const Mode& m = *bending[std::size_t(2 * n - 2 + k)];
        computed(i, k) = m.shape(node, dofIndex(Dof::uy));
        computed(nodes + i, k) = m.shape(node, dofIndex(Dof::uz));
      }
      const double s =
          std::sin(n * std::numbers::pi * line.stations[std::size_t(i)] / kClusterBeamLength);
      exact(i, 0) = s;
      exact(nodes + i, 1) = s;
    }
    ClusterPoint p;
    p.order = n;
    const double fa = bending[std::size_t(2 * n - 2)]->frequencyHz;
    const double fb = bending[std::size_t(2 * n - 1)]->frequencyHz;
    p.relFrequencyGap = std::abs(fa - fb) / fa;
    p.subspaceAngle = largestPrincipalAngle(computed, exact);
    p.vectorAngle = largestPrincipalAngle(computed.col(0), exact.col(0));
    points.push_back(p);
  }
  return points;
}

}  // namespace beamrotor::verify

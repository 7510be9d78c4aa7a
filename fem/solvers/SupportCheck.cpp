#include "fem/solvers/SupportCheck.hpp"

#include <Eigen/Eigenvalues>
#include <Eigen/QR>
#include <sstream>

#include "fem/model/Model.hpp"
#include "fem/solvers/Errors.hpp"
#include "fem/solvers/SparseLU.hpp"

namespace beamrotor {

namespace {
// Regularisation relative to the diagonal: far above round-off (1e-16) so the shifted matrix
// factorises, far below any real stiffness ratio of a supported structure.
constexpr double kRegularisation = 1e-10;
// A mode whose energy, relative to the diagonal, is below this is a zero-energy mode.
constexpr double kZeroEnergy = 1e-8;
// A dof "moves" in a zero-energy mode when its scaled component exceeds this fraction of the
// largest one.
constexpr double kParticipation = 1e-6;
constexpr int kSubspace = 12;  // more than the 6 rigid-body modes of one free 3D body
constexpr int kIterations = 6;
}  // namespace

std::vector<NodeDof> zeroEnergyDofs(const SparseMatrix& Kff, const DofMap& dofs) {
  const int n = int(Kff.rows());
  std::vector<NodeDof> moving;
  if (n == 0) return moving;

  // 1. Dofs with no stiffness at all: nothing resists them.
  Eigen::VectorXd diag = Kff.diagonal();
  const double typical = diag.cwiseAbs().maxCoeff();
  if (!(typical > 0)) {
    for (int i = 0; i < n; ++i) moving.push_back(dofs.dofOf(i));
    return moving;
  }
  std::vector<bool> flagged(n, false);
  for (int i = 0; i < n; ++i)
    if (diag[i] <= 0) flagged[i] = true;

  // 2. Zero-energy modes that couple stiff dofs (rigid-body motion, mechanisms): inverse
  //    subspace iteration in the diagonally scaled metric.
  Eigen::VectorXd D = diag.cwiseMax(typical * 1e-300);
  for (int i = 0; i < n; ++i)
    if (diag[i] <= 0) D[i] = typical;
  SparseMatrix shifted = Kff;
  for (int i = 0; i < n; ++i) shifted.coeffRef(i, i) += kRegularisation * D[i];
  SparseLU lu;
  lu.compute(shifted);
  if (lu.info() == Eigen::Success) {
    const int p = std::min(n, kSubspace);
    Eigen::MatrixXd X = Eigen::MatrixXd::Random(n, p);
    const Eigen::VectorXd sqrtD = D.cwiseSqrt();
    for (int it = 0; it < kIterations; ++it) {
      const Eigen::MatrixXd DX = D.asDiagonal() * X;
      const Eigen::MatrixXd Y = lu.solve(DX);
      const Eigen::MatrixXd scaled = sqrtD.asDiagonal() * Y;
      X = Eigen::HouseholderQR<Eigen::MatrixXd>(scaled).householderQ() *
          Eigen::MatrixXd::Identity(n, p);
      X = sqrtD.cwiseInverse().asDiagonal() * X;  // D-orthonormal columns
    }
    // Rayleigh-Ritz: energy of each D-normalised Ritz vector relative to the diagonal.
    const Eigen::MatrixXd H = X.transpose() * (Kff * X);
    const Eigen::MatrixXd G = X.transpose() * D.asDiagonal() * X;
    Eigen::GeneralizedSelfAdjointEigenSolver<Eigen::MatrixXd> ritz(H, G);
    for (int k = 0; k < p; ++k) {
      if (ritz.eigenvalues()[k] > kZeroEnergy) continue;
      const Eigen::VectorXd v = sqrtD.asDiagonal() * (X * ritz.eigenvectors().col(k));
      const double vmax = v.cwiseAbs().maxCoeff();
      for (int i = 0; i < n; ++i)
        if (std::abs(v[i]) > kParticipation * vmax) flagged[i] = true;
    }
  }
  for (int i = 0; i < n; ++i)
    if (flagged[i]) moving.push_back(dofs.dofOf(i));
  return moving;
}

void throwUnsupported(const Model& model, const std::vector<NodeDof>& moving,
                      const std::string& context) {
  constexpr int kListed = 12;
  std::ostringstream msg;
  msg << context << ": the structure is not fully supported; " << moving.size()
      << " dof(s) can move without straining it: ";
  for (int i = 0; i < int(moving.size()) && i < kListed; ++i)
    msg << (i ? ", " : "") << model.describe(moving[i]);
  if (int(moving.size()) > kListed) msg << ", ... and " << moving.size() - kListed << " more";
  msg << ". Add a support or a spring that holds them.";
  throw UnsupportedStructure(msg.str(), moving);
}

}  // namespace beamrotor

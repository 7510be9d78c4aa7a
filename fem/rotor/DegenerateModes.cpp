// Canonical basis of repeated rotor eigenvalues (see DegenerateModes.hpp).
#include "fem/rotor/DegenerateModes.hpp"

#include <Eigen/Eigenvalues>
#include <cmath>

namespace beamrotor {

namespace {

using Complex = std::complex<double>;

/// The groups of positions whose eigenvalues repeat (each group ascending, size >= 2).
std::vector<std::vector<int>> repeatedGroups(const std::vector<Complex>& lambda) {
  std::vector<std::vector<int>> groups;
  std::vector<bool> taken(lambda.size(), false);
  for (std::size_t i = 0; i < lambda.size(); ++i) {
    if (taken[i] || !(lambda[i].imag() > kRepeatedEigenvalue * std::abs(lambda[i]))) continue;
    std::vector<int> group{int(i)};
    for (std::size_t j = i + 1; j < lambda.size(); ++j)
      if (!taken[j] && std::abs(lambda[j] - lambda[i]) <= kRepeatedEigenvalue * std::abs(lambda[i]))
        group.push_back(int(j)), taken[j] = true;
    if (group.size() > 1) groups.push_back(std::move(group));
  }
  return groups;
}

/// The Hermitian form sum over nodes of conj(a_k) a_l - conj(b_k) b_l on the columns k, l of
/// V, with a = ay uy + az uz and b = by uy + bz uz of each node's translations.
Eigen::MatrixXcd nodalForm(const Eigen::MatrixXcd& V, const DofMap& dofs, int nodeCount,
                           Complex ay, Complex az, Complex by, Complex bz) {
  const int m = int(V.cols());
  Eigen::MatrixXcd H = Eigen::MatrixXcd::Zero(m, m);
  for (int node = 0; node < nodeCount; ++node) {
    const int y = dofs.equation(node, Dof::uy), z = dofs.equation(node, Dof::uz);
    const auto entry = [&](int eq, int col) { return dofs.isFree(eq) ? V(eq, col) : Complex(0); };
    Eigen::VectorXcd a(m), b(m);
    for (int k = 0; k < m; ++k) {
      a[k] = ay * entry(y, k) + az * entry(z, k);
      b[k] = by * entry(y, k) + bz * entry(z, k);
    }
    H += a.conjugate() * a.transpose() - b.conjugate() * b.transpose();
  }
  return H;
}

/// The eigenvectors of the Hermitian H, by ascending eigenvalue; empty when its eigenvalues
/// do not separate (spread below 1e-6 of `scale`, the size of the forms involved).
Eigen::MatrixXcd separatingBasis(const Eigen::MatrixXcd& H, double scale) {
  const Eigen::SelfAdjointEigenSolver<Eigen::MatrixXcd> es(H);
  const Eigen::VectorXd& values = es.eigenvalues();
  for (int k = 0; k + 1 < int(values.size()); ++k)
    if (!(values[k + 1] - values[k] > 1e-6 * scale)) return {};
  return es.eigenvectors();
}

}  // namespace

void canonicalRepeatedModes(const std::vector<Complex>& lambda, Eigen::MatrixXcd& vectors,
                            const DofMap& dofs, int nodeCount) {
  const Complex i(0, 1);
  for (const std::vector<int>& group : repeatedGroups(lambda)) {
    // An orthonormal basis of the eigenspace.
    Eigen::MatrixXcd V(vectors.rows(), Eigen::Index(group.size()));
    for (std::size_t k = 0; k < group.size(); ++k) V.col(Eigen::Index(k)) = vectors.col(group[k]);
    const Eigen::HouseholderQR<Eigen::MatrixXcd> qr(V);
    V = qr.householderQ() * Eigen::MatrixXcd::Identity(V.rows(), V.cols());
    // The whirl form (forward uy + i uz minus backward uy - i uz), ascending: backward first;
    // else the plane form |uz|^2 - |uy|^2, ascending: the y plane first.
    const double scale = 1;  // V has orthonormal columns: both forms are bounded by 1 (x 4)
    Eigen::MatrixXcd basis = separatingBasis(nodalForm(V, dofs, nodeCount, 1, i, 1, -i), scale);
    if (basis.size() == 0)
      basis = separatingBasis(nodalForm(V, dofs, nodeCount, 0, 1, 1, 0), scale);
    if (basis.size() == 0) continue;  // no physical preference: keep the solver's basis
    const Eigen::MatrixXcd canonical = V * basis;
    for (std::size_t k = 0; k < group.size(); ++k)
      vectors.col(group[k]) = canonical.col(Eigen::Index(k));
  }
}

}  // namespace beamrotor

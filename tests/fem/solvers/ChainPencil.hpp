// A test pencil whose eigenvalues are known in closed form.
#pragma once

#include <algorithm>
#include <cmath>
#include <numbers>
#include <vector>

#include "fem/assembly/Assembly.hpp"

namespace beamrotor::test {

/// A chain pencil of n dofs whose eigenvalues are known in closed form: with T the n x n
/// tridiagonal matrix of ones beside a zero diagonal, whose eigenvalues are 2 cos(j pi / (n+1)),
/// j = 1..n, the pencil (a I + b T, c I + d T) has the eigenvalues
/// (a + 2 b cos t_j) / (c + 2 d cos t_j) (both matrices share T's eigenvectors).
struct ChainPencil {
  SparseMatrix K, M;
  std::vector<double> exact;  // ascending
};

inline ChainPencil chainPencil(int n, double a, double b, double c, double d) {
  auto tridiagonal = [n](double diag, double off) {
    std::vector<Eigen::Triplet<double>> t;
    for (int i = 0; i < n; ++i) {
      t.emplace_back(i, i, diag);
      if (off != 0 && i + 1 < n) {
        t.emplace_back(i, i + 1, off);
        t.emplace_back(i + 1, i, off);
      }
    }
    SparseMatrix A(n, n);
    A.setFromTriplets(t.begin(), t.end());
    return A;
  };
  ChainPencil p{tridiagonal(a, b), tridiagonal(c, d), {}};
  for (int j = 1; j <= n; ++j) {
    const double twoCos = 2 * std::cos(j * std::numbers::pi / (n + 1));
    p.exact.push_back((a + b * twoCos) / (c + d * twoCos));
  }
  std::sort(p.exact.begin(), p.exact.end());
  return p;
}

}  // namespace beamrotor::test

// A second method for the St Venant torsion constant of any solid outline (no holes), for the
// tests of the open sections' torsion formulas: Prandtl's stress function phi, zero on the
// boundary with lap(phi) = -2 inside, and It = 2 int phi dA. Finite differences on a square
// grid: the nodes inside the outline are the unknowns; where a grid line leaves the outline
// between two nodes the five-point stencil takes the boundary's true distance (Shortley &
// Weller 1938). The integral sums phi over the nodes' cells. Measured, the result converges at
// first order in the spacing (a 10 x 2 rectangle against its series: 9.5e-3, 4.9e-3, 2.5e-3 at
// spacings b/40, b/80, b/160), so two grids are extrapolated linearly: 2 J(h/2) - J(h).
#pragma once

#include <Eigen/SparseCore>
#include <Eigen/SparseLU>
#include <algorithm>
#include <array>
#include <vector>

#include "fem/model/SectionOutline.hpp"

namespace beamrotor::test {

using TorsionPolygon = std::vector<std::array<double, 2>>;

inline bool insideTorsionPolygon(const TorsionPolygon& poly, double y, double z) {
  bool in = false;
  for (std::size_t i = 0, j = poly.size() - 1; i < poly.size(); j = i++) {
    const auto& a = poly[i];
    const auto& b = poly[j];
    if ((a[1] > z) != (b[1] > z) && y < (b[0] - a[0]) * (z - a[1]) / (b[1] - a[1]) + a[0])
      in = !in;
  }
  return in;
}

/// Distance from (y, z) along the unit grid direction (dy, dz) to the polygon's boundary, or
/// `reach` when the boundary is farther.
inline double boundaryDistance(const TorsionPolygon& poly, double y, double z, double dy,
                               double dz, double reach) {
  double nearest = reach;
  for (std::size_t i = 0, j = poly.size() - 1; i < poly.size(); j = i++) {
    const double ey = poly[i][0] - poly[j][0], ez = poly[i][1] - poly[j][1];
    const double cross = dy * ez - dz * ey;
    if (cross == 0) continue;
    const double ry = poly[j][0] - y, rz = poly[j][1] - z;
    const double along = (ry * ez - rz * ey) / cross, onEdge = (ry * dz - rz * dy) / cross;
    if (along > 0 && along < nearest && onEdge >= 0 && onEdge <= 1) nearest = along;
  }
  return nearest;
}

/// It = 2 int phi dA on a grid of spacing h (nodes at cell centres, offset by a fraction of a
/// cell so that no node falls on an edge of the outline).
inline double prandtlTorsion(const TorsionPolygon& poly, double h) {
  double y0 = poly[0][0], y1 = y0, z0 = poly[0][1], z1 = z0;
  for (const auto& p : poly) {
    y0 = std::min(y0, p[0]), y1 = std::max(y1, p[0]);
    z0 = std::min(z0, p[1]), z1 = std::max(z1, p[1]);
  }
  const int ny = static_cast<int>((y1 - y0) / h) + 2, nz = static_cast<int>((z1 - z0) / h) + 2;
  const auto yAt = [&](int i) { return y0 + (i + 0.5) * h + 1.3e-4 * h; };
  const auto zAt = [&](int k) { return z0 + (k + 0.5) * h + 2.9e-4 * h; };
  std::vector<int> unknown(static_cast<std::size_t>(ny) * nz, -1);
  const auto at = [&](int i, int k) -> int& { return unknown[static_cast<std::size_t>(i) * nz + k]; };
  int n = 0;
  for (int i = 0; i < ny; ++i)
    for (int k = 0; k < nz; ++k)
      if (insideTorsionPolygon(poly, yAt(i), zAt(k))) at(i, k) = n++;

  std::vector<Eigen::Triplet<double>> entries;
  const int step[4][2] = {{1, 0}, {-1, 0}, {0, 1}, {0, -1}};
  for (int i = 0; i < ny; ++i)
    for (int k = 0; k < nz; ++k) {
      const int row = at(i, k);
      if (row < 0) continue;
      double arm[4];
      int neighbour[4];
      for (int d = 0; d < 4; ++d) {
        const int ii = i + step[d][0], kk = k + step[d][1];
        const int q = ii >= 0 && ii < ny && kk >= 0 && kk < nz ? at(ii, kk) : -1;
        arm[d] = boundaryDistance(poly, yAt(i), zAt(k), step[d][0], step[d][1], h);
        neighbour[d] = q >= 0 && arm[d] >= h ? q : -1;
      }
      double diagonal = 0;
      for (int axis = 0; axis < 2; ++axis) {
        const double a = arm[2 * axis], b = arm[2 * axis + 1];
        const double toA = 2 / (a * (a + b)), toB = 2 / (b * (a + b));
        diagonal += toA + toB;
        if (neighbour[2 * axis] >= 0) entries.emplace_back(row, neighbour[2 * axis], -toA);
        if (neighbour[2 * axis + 1] >= 0) entries.emplace_back(row, neighbour[2 * axis + 1], -toB);
      }
      entries.emplace_back(row, row, diagonal);
    }
  Eigen::SparseMatrix<double> laplacian(n, n);
  laplacian.setFromTriplets(entries.begin(), entries.end());
  // Shortley-Weller's stencil is not symmetric at the boundary: a general sparse LU.
  Eigen::SparseLU<Eigen::SparseMatrix<double>> lu(laplacian);
  const Eigen::VectorXd phi = lu.solve(Eigen::VectorXd::Constant(n, 2.0));
  return 2 * phi.sum() * h * h;
}

/// The stress function's It extrapolated from grids of spacing h and h / 2.
inline double extrapolatedTorsion(const TorsionPolygon& poly, double h) {
  return 2 * prandtlTorsion(poly, h / 2) - prandtlTorsion(poly, h);
}

/// The same for an outline of StandardSections (each rounded corner drawn by 64 chords).
inline double extrapolatedTorsion(const OutlineLoop& outline, double h) {
  return extrapolatedTorsion(outlinePolygon(outline, 64), h);
}

}  // namespace beamrotor::test

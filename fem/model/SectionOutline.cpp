#include "fem/model/SectionOutline.hpp"

#include <array>
#include <cmath>
#include <numbers>
#include <stdexcept>
#include <string>

#include "fem/model/GaussLegendre.hpp"

namespace beamrotor {

namespace {

/// 16 points integrate polynomials up to degree 31 exactly; along an arc the integrands below
/// are trigonometric polynomials of degree <= 4 over at most a half turn, where 16 points are
/// exact to round-off.
using GaussRule = GaussLegendre<16>;

/// The boundary integrals of Green's theorem (material to the left of the path):
/// A = int y dz, Sy = int y^2/2 dz (= int y dA), Sz = -int z^2/2 dy, Iyy = -int z^3/3 dy,
/// Izz = int y^3/3 dz, Iyz = int y^2 z/2 dz; all about the drawing's origin.
struct Moments {
  double A = 0, Sy = 0, Sz = 0, Iyy = 0, Izz = 0, Iyz = 0;
  void add(double y, double z, double dy, double dz, double weight) {
    A += weight * y * dz;
    Sy += weight * y * y / 2 * dz;
    Sz -= weight * z * z / 2 * dy;
    Iyy -= weight * z * z * z / 3 * dy;
    Izz += weight * y * y * y / 3 * dz;
    Iyz += weight * y * y * z / 2 * dz;
  }
};

/// One corner of a loop after rounding: where its arc starts and ends, its centre and its
/// signed turning angle (positive: a left turn, a convex corner of an outer loop).
struct Rounded {
  double y1, z1, y2, z2;  ///< arc start (on the incoming edge) and end (on the outgoing edge)
  double cy, cz, radius;
  double start, turn;     ///< angle of the start point about the centre, and the arc's sweep
                          ///< (0 for a sharp corner)
  double bend;            ///< the outline's turn at the corner, rounded or not
  double inAngle;         ///< direction of the incoming edge
};

std::vector<Rounded> roundCorners(const OutlineLoop& loop) {
  const int n = int(loop.size());
  if (n < 3) throw std::invalid_argument("a section outline needs at least three corners");
  std::vector<Rounded> out(n);
  std::vector<double> used(n, 0);  // tangent lengths taken from edge i (from corner i to i+1)
  for (int i = 0; i < n; ++i) {
    const OutlineCorner& p = loop[(i + n - 1) % n];
    const OutlineCorner& c = loop[i];
    const OutlineCorner& q = loop[(i + 1) % n];
    const double inA = std::atan2(c.z - p.z, c.y - p.y), outA = std::atan2(q.z - c.z, q.y - c.y);
    const double turn = std::remainder(outA - inA, 2 * std::numbers::pi);
    const double r = c.radius;
    if (!(std::isfinite(r) && r >= 0))
      throw std::invalid_argument("corner radii must be non-negative");
    const double tangent = r * std::tan(std::abs(turn) / 2);
    Rounded& k = out[i];
    k.y1 = c.y - tangent * std::cos(inA);
    k.z1 = c.z - tangent * std::sin(inA);
    k.y2 = c.y + tangent * std::cos(outA);
    k.z2 = c.z + tangent * std::sin(outA);
    // The centre lies on the inner side of the turn, r from the incoming edge.
    const double side = turn >= 0 ? 1 : -1;
    k.cy = k.y1 - side * r * std::sin(inA);
    k.cz = k.z1 + side * r * std::cos(inA);
    k.radius = r;
    k.start = inA - side * std::numbers::pi / 2;
    k.turn = r > 0 ? turn : 0;
    k.bend = turn;
    k.inAngle = inA;
    used[(i + n - 1) % n] += tangent;
    used[i] += tangent;
  }
  for (int i = 0; i < n; ++i) {
    const OutlineCorner& a = loop[i];
    const OutlineCorner& b = loop[(i + 1) % n];
    if (used[i] > std::hypot(b.y - a.y, b.z - a.z) * (1 + 1e-12))
      throw std::invalid_argument("the corner radii of a section do not fit its edges (edge " +
                                  std::to_string(i + 1) + " of its outline)");
  }
  return out;
}

void addLoop(const OutlineLoop& loop, Moments& m) {
  static const GaussRule rule;
  const std::vector<Rounded> corners = roundCorners(loop);
  const int n = int(corners.size());
  for (int i = 0; i < n; ++i) {
    const Rounded& k = corners[i];
    // The arc at corner i: y = cy + r cos t, z = cz + r sin t, t from start over turn.
    if (k.turn != 0)
      for (int g = 0; g < GaussRule::n; ++g) {
        const double t = k.start + k.turn * (1 + rule.x[g]) / 2, half = k.turn / 2;
        m.add(k.cy + k.radius * std::cos(t), k.cz + k.radius * std::sin(t),
              -k.radius * std::sin(t) * half, k.radius * std::cos(t) * half, rule.w[g]);
      }
    // The straight edge from this corner's arc end to the next corner's arc start.
    const Rounded& next = corners[(i + 1) % n];
    const double dy = (next.y1 - k.y2) / 2, dz = (next.z1 - k.z2) / 2;
    for (int g = 0; g < GaussRule::n; ++g) {
      const double u = (1 + rule.x[g]) / 2;
      m.add(k.y2 + u * (next.y1 - k.y2), k.z2 + u * (next.z1 - k.z2), dy, dz, rule.w[g]);
    }
  }
}

}  // namespace

OutlineProperties outlineProperties(const std::vector<OutlineLoop>& loops) {
  Moments m;
  for (const OutlineLoop& loop : loops) addLoop(loop, m);
  if (!(m.A > 0)) throw std::invalid_argument("a section outline must enclose a positive area");
  OutlineProperties p;
  p.A = m.A;
  p.cy = m.Sy / m.A;
  p.cz = m.Sz / m.A;
  p.Iyy = m.Iyy - m.A * p.cz * p.cz;
  p.Izz = m.Izz - m.A * p.cy * p.cy;
  p.Iyz = m.Iyz - m.A * p.cy * p.cz;
  // int y'^2 = mean + R cos(2 alpha - phi) with phi = atan2(2 Iyz, Izz - Iyy): largest at
  // alpha = phi / 2, where the product of inertia vanishes.
  const double mean = (p.Iyy + p.Izz) / 2, R = std::hypot((p.Izz - p.Iyy) / 2, p.Iyz);
  const bool principal = std::abs(p.Iyz) <= 1e-12 * mean;
  p.principalAngle = principal ? 0 : std::atan2(2 * p.Iyz, p.Izz - p.Iyy) / 2;
  p.principalIz = principal ? p.Izz : mean + R;
  p.principalIy = principal ? p.Iyy : mean - R;
  return p;
}

std::vector<StressFibre> outlineFibres(const OutlineLoop& outer, const OutlineProperties& p) {
  const double c = std::cos(p.principalAngle), s = std::sin(p.principalAngle);
  const auto local = [&](double y, double z) {
    return std::array<double, 2>{c * (y - p.cy) + s * (z - p.cz), -s * (y - p.cy) + c * (z - p.cz)};
  };
  std::vector<StressFibre> fibres;
  for (const Rounded& k : roundCorners(outer)) {
    // A right turn (or none) of the outer loop is a re-entrant corner: never extreme.
    if (!(k.bend > 0)) continue;
    if (k.radius == 0) {  // the vertex itself
      const auto [y, z] = local(k.y1, k.z1);
      fibres.push_back(StressFibre{y, z, 0, 0, 0});
      continue;
    }
    const auto [y, z] = local(k.cy, k.cz);
    // Outward normals on the arc run from the incoming edge's right normal over the turn.
    fibres.push_back(StressFibre{y, z, k.radius, k.inAngle - std::numbers::pi / 2 - p.principalAngle, k.turn});
  }
  return fibres;
}

std::vector<std::array<double, 2>> outlinePolygon(const OutlineLoop& loop, int segmentsPerArc) {
  std::vector<std::array<double, 2>> points;
  for (const Rounded& k : roundCorners(loop)) {
    if (k.turn == 0) {
      points.push_back({k.y1, k.z1});
      continue;
    }
    for (int j = 0; j <= segmentsPerArc; ++j) {
      const double t = k.start + k.turn * j / segmentsPerArc;
      points.push_back({k.cy + k.radius * std::cos(t), k.cz + k.radius * std::sin(t)});
    }
  }
  return points;
}

}  // namespace beamrotor

#include "fem/model/BendingModuli.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <stdexcept>

namespace beamrotor {

namespace {

using Point = std::array<double, 2>;

/// Area and first moment about the line n.p = ref of the part of the polygons where n.p >= c, by
/// clipping each polygon to that half-plane (Sutherland-Hodgman). A non-convex polygon may come
/// out with edges running back along the cut, which enclose no area: the shoelace sums stay
/// exact. Holes are clockwise and subtract.
struct Part {
  double area = 0, moment = 0;
};

Part clippedPart(const std::vector<std::vector<Point>>& polygons, double ny, double nz, double c,
                 double ref) {
  Part part;
  for (const std::vector<Point>& poly : polygons) {
    std::vector<Point> kept;
    const std::size_t n = poly.size();
    for (std::size_t i = 0; i < n; ++i) {
      const Point& a = poly[i];
      const Point& b = poly[(i + 1) % n];
      const double sa = ny * a[0] + nz * a[1] - c, sb = ny * b[0] + nz * b[1] - c;
      if (sa >= 0) kept.push_back(a);
      if ((sa >= 0) != (sb >= 0)) {
        const double u = sa / (sa - sb);
        kept.push_back({a[0] + u * (b[0] - a[0]), a[1] + u * (b[1] - a[1])});
      }
    }
    // A fan of triangles (origin, a, b): signed area cross / 2, and the integral of the
    // linear s = n.p - ref the area times its mean over the three corners.
    const std::size_t m = kept.size();
    for (std::size_t i = 0; i < m; ++i) {
      const Point& a = kept[i];
      const Point& b = kept[(i + 1) % m];
      const double cross = a[0] * b[1] - b[0] * a[1];
      const double sa = ny * a[0] + nz * a[1] - ref, sb = ny * b[0] + nz * b[1] - ref;
      part.area += cross / 2;
      part.moment += cross / 2 * (sa + sb - ref) / 3;
    }
  }
  return part;
}

/// The polygons of the loops, each arc drawn by `chords` chords.
std::vector<std::vector<Point>> polygonsOf(const std::vector<OutlineLoop>& loops, int chords) {
  std::vector<std::vector<Point>> polygons;
  for (const OutlineLoop& loop : loops) polygons.push_back(outlinePolygon(loop, chords));
  return polygons;
}

/// int |n.p - c| dA over the polygons, c the line that halves their area: bisection on c (the
/// area above it falls as c rises) down to round-off of the extent [lo, hi].
double plasticModulus(const std::vector<std::vector<Point>>& polygons, double ny, double nz,
                      double lo, double hi) {
  const double total = clippedPart(polygons, ny, nz, lo - 1, 0).area;
  double a = lo, b = hi;
  for (int i = 0; i < 200 && b - a > 1e-15 * (hi - lo); ++i) {
    const double c = (a + b) / 2;
    (clippedPart(polygons, ny, nz, c, 0).area > total / 2 ? a : b) = c;
  }
  // int |n.p - c| dA = (moment above c) - (moment below c) = 2 (above) - (all).
  const double c = (a + b) / 2;
  return 2 * clippedPart(polygons, ny, nz, c, c).moment -
         clippedPart(polygons, ny, nz, lo - 1, c).moment;
}

}  // namespace

BendingModuli bendingModuli(const std::vector<OutlineLoop>& loops, double ny, double nz,
                            double I) {
  const OutlineProperties p = outlineProperties(loops);
  const std::vector<std::vector<Point>> fine = polygonsOf(loops, 512);
  double lo = 0, hi = 0;  // the extent of n.p
  bool first = true;
  for (const auto& poly : fine)
    for (const Point& q : poly) {
      const double s = ny * q[0] + nz * q[1];
      lo = first ? s : std::min(lo, s);
      hi = first ? s : std::max(hi, s);
      first = false;
    }
  const double centroid = ny * p.cy + nz * p.cz;
  BendingModuli w;
  w.Wel = I / std::max(hi - centroid, centroid - lo);
  // Chords cut the arcs short by an area of order 1/n^2: two polygons (n = 256, 512) and
  // Richardson's extrapolation leave an error of order 1/n^4.
  const double coarse = plasticModulus(polygonsOf(loops, 256), ny, nz, lo, hi);
  w.Wpl = (4 * plasticModulus(fine, ny, nz, lo, hi) - coarse) / 3;
  if (!(w.Wpl > 0 && w.Wel > 0)) throw std::invalid_argument("section moduli of an empty outline");
  return w;
}

}  // namespace beamrotor

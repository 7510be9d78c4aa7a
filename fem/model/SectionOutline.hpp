// The area properties of a cross-section drawn as straight-sided loops whose corners may be
// rounded (root fillets, toe and corner radii): area, centroid, second moments, principal
// axes and the fibres where a linear stress field peaks. Exact for such outlines: Green's
// theorem turns every area integral into a boundary integral, polynomial along the straight
// edges and a low-degree trigonometric polynomial along the arcs (both integrated by
// Gauss-Legendre rules far beyond their degree).
#pragma once

#include <array>
#include <vector>

#include "fem/model/Section.hpp"

namespace beamrotor {

/// A corner of an outline: its sharp vertex (y, z) and the radius of the circular arc that
/// rounds it, tangent to both edges (0: sharp).
struct OutlineCorner {
  double y = 0, z = 0;
  double radius = 0;
};

/// A closed loop of corners. The material lies to the left when walking the loop: the outer
/// boundary counter-clockwise (from +y towards +z), a hole clockwise.
using OutlineLoop = std::vector<OutlineCorner>;

/// Area properties about the centroid in the drawing's axes.
struct OutlineProperties {
  double A = 0;                   ///< area
  double cy = 0, cz = 0;          ///< centroid
  double Iyy = 0, Izz = 0;        ///< int z^2 dA (about y) and int y^2 dA (about z)
  double Iyz = 0;                 ///< product int y z dA
  /// Rotation (rad, from +y towards +z) of the principal axes y', z': 0 when the drawing's
  /// axes are principal already (Iyz = 0 to round-off); otherwise chosen so that the second
  /// moment about z' (int y'^2) is the larger one.
  double principalAngle = 0;
  double principalIy = 0, principalIz = 0;  ///< int z'^2 dA and int y'^2 dA
};

/// Properties of the loops (the first the outer boundary, the rest holes). Throws
/// std::invalid_argument when a corner's radius does not fit its edges.
OutlineProperties outlineProperties(const std::vector<OutlineLoop>& loops);

/// The convex corners of the outer loop as stress fibres (sharp points and arcs) in principal
/// axes: coordinates from the centroid, rotated by -principalAngle. The largest of a linear
/// field over the section lies on them.
std::vector<StressFibre> outlineFibres(const OutlineLoop& outer, const OutlineProperties& p);

/// The loop as a polygon: sharp corners as they are, each rounded corner's arc by
/// `segmentsPerArc` chords (their ends on the arc), in the loop's order and orientation.
std::vector<std::array<double, 2>> outlinePolygon(const OutlineLoop& loop, int segmentsPerArc);

}  // namespace beamrotor

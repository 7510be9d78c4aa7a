// Elastic and plastic section moduli of an outline (SectionOutline) for bending about an axis
// through its centroid: Wel = I / (largest distance of the outline from the axis), and Wpl the
// sum of the first moments of the two halves of the area about the plastic neutral axis (the
// line parallel to the bending axis that halves the area; the centroidal axis only for a
// section symmetric about it).
#pragma once

#include <vector>

#include "fem/model/SectionOutline.hpp"

namespace beamrotor {

struct BendingModuli {
  double Wel = 0;  ///< elastic modulus, m^3
  double Wpl = 0;  ///< plastic modulus, m^3
};

/// The moduli for bending that strains fibres in proportion to their distance along the unit
/// direction (ny, nz) (drawing axes): for the direction +y, bending about the axis parallel to
/// z. `I` is the second moment of area about that centroidal axis (for Wel). The plastic
/// modulus clips polygons that draw each rounded corner by chords (256 and 512 of them,
/// extrapolated: the chords' shortfall falls as 1/n^2); the farthest fibre is the farthest
/// of 512 points along each arc, short of the arc's by at most r (1 - cos(pi/2048)), 1.2e-6 r.
BendingModuli bendingModuli(const std::vector<OutlineLoop>& loops, double ny, double nz, double I);

}  // namespace beamrotor

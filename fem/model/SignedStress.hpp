// Signed stresses of a section, for diagrams that show which fibre is in tension and which in
// compression (the magnitudes are maxNormalStress and maxShearStress).
#pragma once

#include "fem/model/LineElement.hpp"
#include "fem/model/Section.hpp"

namespace beamrotor {

/// The largest of d . p over the fibre's points p (its support function in direction
/// (dy, dz), local axes, m): the fibre's farthest reach along d.
double fibreSupport(const StressFibre& fibre, double dy, double dz);

/// Normal stress (Pa, tension positive) of N and Mz at the section's extreme fibres along
/// the local y axis: `top` at the largest y, `bottom` at the smallest (in a planar model local
/// y is the upward normal of the line). My does not enter (it is zero in a planar model; the
/// largest |sigma| with all resultants is maxNormalStress). NaN for a section without fibres.
struct YFibreStresses {
  double top = 0, bottom = 0;
};
YFibreStresses yFibreStresses(const Section& s, const SectionForces& f);

/// The largest shear stress of Vy alone (Pa), with the sign of Vy; likewise of Vz alone.
double signedShearY(const Section& s, const SectionForces& f);
double signedShearZ(const Section& s, const SectionForces& f);

}  // namespace beamrotor

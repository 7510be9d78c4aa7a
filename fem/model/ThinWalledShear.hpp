// Transverse shear of thin-walled sections from their midlines (Jourawski's shear flow
// q = V Q / I, Q the first moment of the wall cut off beyond a point): the shear coefficient
// from the flow's strain energy and the largest shear stress. The walls are straight strips of
// constant thickness; fillets and corner radii are left out (an error of order t / h).
#pragma once

#include <vector>

namespace beamrotor {

/// A straight wall: its midline from (y0, z0) to (y1, z1) (principal axes, from the
/// centroid) and its thickness t.
struct Wall {
  double y0 = 0, z0 = 0, y1 = 0, z1 = 0;
  double t = 0;
};

/// The shear flow along a chain of walls walked from its first wall's start, for shear along
/// the unit direction (dy, dz): Q(s) = Q0 + int t (dy y + dz z) ds.
struct ShearFlow {
  double energy = 0;  ///< int Q^2 / t ds over the chain
  double end = 0;     ///< Q at the chain's end
  double peak = 0;    ///< largest |Q| / t along it
};
ShearFlow shearFlow(const std::vector<Wall>& chain, double Q0, double dy, double dz);

/// Shear properties for shear along one principal axis, from the energy E = int Q^2/t ds over
/// the whole section, the largest Q/t and the midline second moment I about the other axis:
/// tau = V Q / (I t), so the strain energy per length V^2 E / (2 G I^2) equals
/// V^2 / (2 G kappa A): kappa = I^2 / (A E) (e.g. Pilkey, Analysis and Design of Elastic
/// Beams, 2002, ch. 6, the shear form factor 1/kappa); tau_max = V peak / I, as a factor of
/// V/A: A peak / I.
struct ThinWalledShear {
  double kappa = 0;  ///< shear coefficient (shear area / A)
  double peak = 0;   ///< tau_max A / V
};
ThinWalledShear thinWalledShear(double energy, double peak, double I, double A);

/// The midline second moment int t c^2 ds of the walls, c = dy y + dz z the distance from
/// the axis normal to (dy, dz).
double midlineSecondMoment(const std::vector<Wall>& walls, double dy, double dz);

}  // namespace beamrotor

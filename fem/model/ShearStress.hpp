// Transverse shear stress of a cross-section from its shear forces: the largest value over the
// section, which for the shapes below lies on the neutral axis (the centre of a solid section).
// Torsion is not included: these are the stresses of the shear force alone.
#pragma once

#include "fem/model/LineElement.hpp"
#include "fem/model/Section.hpp"

namespace beamrotor {

/// k in tau_max = k V / A for the section's shape, V the resultant shear force:
/// - solid circle: k = (3 + 2 nu) / (2 (1 + nu)), the elasticity solution of a bent circular
///   bar (Timoshenko & Goodier, Theory of Elasticity, 3rd ed., art. 124; 1.385 for nu = 0.3;
///   the elementary Jourawski value 4/3 ignores the Poisson effect across the width);
/// - tube, outer radius R, inner r: k = 4 (R^2 + R r + r^2) / (3 (R^2 + r^2)), Jourawski's
///   formula V Q / (I b) at the neutral axis (Gere & Goodno, Mechanics of Materials, 5.9):
///   4/3 for r = 0, 2 for a thin wall;
/// - rectangle: k = 3/2 (Jourawski; Gere & Goodno, 5.8);
/// - general section: k = 1, the mean shear stress V/A (its shape is unknown);
/// - thin-walled standard shapes (I, channel, angle, rectangular hollow): the larger of their
///   factors along y and z, Jourawski's V Q / (I t) at its largest over the midline
///   (StandardSections, ThinWalledShear).
double shearStressFactor(const Section& s);

/// Largest transverse shear stress (Pa) from Vy and Vz: k hypot(Vy, Vz) / A. For the circle
/// and tube the section is axisymmetric, so the resultant acts like a single shear force; for a
/// rectangle both parabolic distributions peak at the centre, where they add as vectors. For
/// the thin-walled shapes (kY |Vy| + kZ |Vz|) / A: exact for shear along one axis, and an
/// upper bound under both, whose peaks may lie at different places of the wall.
double maxShearStress(const Section& s, const SectionForces& f);

}  // namespace beamrotor

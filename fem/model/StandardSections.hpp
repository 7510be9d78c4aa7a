// Standard structural shapes from their dimensions (m): rolled and welded I/H sections,
// channels, angles and rectangular hollow sections. Each gets its area and second moments
// from the exact outline with its fillets (SectionOutline), its torsion constant from the
// formula named at its function, its shear coefficients and peak shear stress factors from
// the thin-walled shear flow of its midline (ThinWalledShear), and its stress fibres (the
// outline's convex corners). Local axes: y along the depth h (the web of I and channel
// sections, so a planar model bends the strong way, about z), z along the width b.
#pragma once

#include <string>
#include <vector>

#include "fem/model/Section.hpp"
#include "fem/model/SectionOutline.hpp"

namespace beamrotor {

/// The outlines the shapes below are drawn from (drawing axes: y along the depth h, z along
/// the width b; the I-section and the rectangle centred on the origin, the channel with its
/// web's back on z = 0, the angle with its heel at the origin and the leg h along y).
std::vector<OutlineLoop> iSectionOutline(double h, double b, double tw, double tf, double r);
std::vector<OutlineLoop> channelOutline(double h, double b, double tw, double tf, double r,
                                        double rToe, double taper);
std::vector<OutlineLoop> angleOutline(double h, double b, double t, double r, double rToe);
std::vector<OutlineLoop> hollowRectangleOutline(double h, double b, double t, double ro,
                                                double ri);

/// Doubly symmetric I/H section: depth h, flange width b, web tw, flanges tf, root radius r
/// (0 for a welded section, whose fillet welds are not counted). The published tables' y-y
/// (strong) axis is this z: their Iy is Section::Iz.
Section iSection(std::string name, const Material& m, double h, double b, double tw, double tf,
                 double r);

/// Channel: depth h, flange width b (from the web's back), web tw, flanges tf, root radius r,
/// flange toe radius rToe (inner corner of the flange tips), and the slope of the flanges'
/// inner faces, `taper` (0 for parallel flanges as UPE and PFC; 0.08 for UPN up to 300,
/// whose tf is measured halfway along the flange, b/2 from the web's back, DIN 1026-1). The
/// web's back lies at z = -e (e from the centroid, the tables' e or e_y); the shear centre
/// lies behind the web and is not modelled: loads act through the centroid. Torsion and
/// shear take the flanges at their mean thickness tf.
Section channelSection(std::string name, const Material& m, double h, double b, double tw,
                       double tf, double r, double rToe, double taper = 0);

/// Angle with legs h (drawn along y) and b (along z), thickness t, root radius r and toe
/// radius rToe. Its principal axes are inclined to the legs: local y and z are the principal
/// axes, z the major one (the tables' u-u, Iz = Iu, Iy = Iv); the legs lie at
/// -principalAngle from them (see angleLegAngle).
Section angleSection(std::string name, const Material& m, double h, double b, double t, double r,
                     double rToe);
/// The angle (rad) from the leg h to the local y axis, turning towards the leg b.
double angleLegAngle(double h, double b, double t, double r, double rToe);

/// Rectangular (square) hollow section: depth h (along y), width b, wall t, outer and inner
/// corner radii ro, ri (0: sharp).
Section hollowRectangleSection(std::string name, const Material& m, double h, double b, double t,
                               double ro, double ri);

}  // namespace beamrotor

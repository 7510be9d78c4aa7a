// Materials and cross-sections as shared values (several elements point at one section).
#pragma once

#include <string>
#include <vector>

namespace beamrotor {

/// Isotropic linear-elastic material. E, G in Pa, rho in kg/m^3.
struct Material {
  std::string name;
  double E = 0;
  double nu = 0.3;  ///< Poisson's ratio; G = E / (2 (1 + nu)) unless G is given
  double G = 0;
  double rho = 0;
  double alpha = 0;  ///< coefficient of thermal expansion (1/K); 0 when not given

  /// From E, nu (G derived). Throws std::invalid_argument on non-physical values.
  static Material fromEnu(std::string name, double E, double nu, double rho);
};

/// A place on a section's outline where the normal stress can be largest (local y, z from the
/// centroid, m): a sharp corner (radius 0), or a convex circular arc of `radius` about (y, z)
/// spanning the outward directions from angle `from` through `from + sweep` (rad, measured from
/// +y towards +z; sweep 2 pi for a whole circle). The extreme of a linear stress field over
/// the section lies at one of its fibres (it is attained on the outline's convex hull).
struct StressFibre {
  double y = 0, z = 0;
  double radius = 0;
  double from = 0, sweep = 0;
};

/// Cross-section properties in the element's local frame (x along the axis, y and z the
/// principal axes). Areas m^2, second moments m^4.
struct Section {
  enum class Shape { circle, tube, rectangle, general, iSection, channel, angle, hollowRectangle };

  std::string name;
  Shape shape = Shape::general;
  Material material;
  double A = 0;       ///< area
  double Iy = 0;      ///< second moment about local y (bending in the x-z plane)
  double Iz = 0;      ///< second moment about local z (bending in the x-y plane)
  double J = 0;       ///< torsion constant
  double kappaY = 0;  ///< shear coefficient for shear along local y (0: shear-rigid)
  double kappaZ = 0;  ///< shear coefficient for shear along local z
  double outerY = 0;  ///< distance from the axis to the outer fibre along y (stress recovery)
  double outerZ = 0;  ///< ... along z
  double depth = 0;   ///< overall depth for slenderness (diameter or height)
  /// Where the normal stress can be largest (see StressFibre); empty when unknown (a
  /// `general` section without its extent), and then no stress can be recovered.
  std::vector<StressFibre> fibres;
  /// Thin-walled shapes: tau_max = shearPeakY |Vy| / A for shear along y alone (and Z for z);
  /// 0 for the solid and round shapes, whose factor shearStressFactor derives from the shape.
  double shearPeakY = 0, shearPeakZ = 0;

  double EA() const { return material.E * A; }
  double EIy() const { return material.E * Iy; }
  double EIz() const { return material.E * Iz; }
  double GJ() const { return material.G * J; }
  double rhoA() const { return material.rho * A; }
  /// Polar moment of area Iy + Iz (rotary inertia in torsion).
  double Ip() const { return Iy + Iz; }

  /// Solid circle of diameter D; Cowper's kappa = 6 (1 + nu) / (7 + 6 nu).
  static Section circle(std::string name, const Material& m, double D);
  /// Tube of outer diameter D and wall t; Cowper's thin/thick tube kappa.
  static Section tube(std::string name, const Material& m, double D, double t);
  /// Rectangle b (along local z) by h (along local y); Cowper's kappa = 10 (1 + nu) / (12 + 11 nu).
  static Section rectangle(std::string name, const Material& m, double b, double h);
  /// Any section from its properties; kappa = 0 means shear-rigid. depth > 0 sets the extent
  /// along y and z to depth (setExtent); depth 0 leaves the extent unknown (no fibres).
  static Section general(std::string name, const Material& m, double A, double Iy, double Iz,
                         double J, double kappaY, double kappaZ, double depth);

  /// The outer fibres of a section whose extreme points are the corners of its bounding box,
  /// alongY (depth) by alongZ (width), centred on the centroid; 0 for an extent that no
  /// bending can load (a planar model's z).
  void setExtent(double alongY, double alongZ);
};

/// The corners (+-cy, +-cz) as sharp fibres; two points when cy or cz is 0.
std::vector<StressFibre> cornerFibres(double cy, double cz);

}  // namespace beamrotor

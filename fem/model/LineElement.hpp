// Elements with an axis and a cross-section (beams, shafts): what recovery and output need
// beyond the plain Element interface.
#pragma once

#include <array>
#include <memory>

#include "fem/model/Element.hpp"
#include "fem/model/Section.hpp"

namespace beamrotor {

/// Stress resultants on the cross-section face whose outward normal is the local +x axis
/// (element frame): N axial (tension positive), Vy, Vz shear, T torque, My, Mz bending.
/// Units N and N m. With this convention dMz/dx = -Vy and dMy/dx = Vz.
struct SectionForces {
  double N = 0, Vy = 0, Vz = 0, T = 0, My = 0, Mz = 0;
};

/// Resultants along an element as polynomials in s, the fraction of its length:
/// value(s) = c[0] + c[1] s + c[2] s^2 + c[3] s^3 component by component. Under the span
/// loads the elements carry (varying linearly along the element) the forces are at most
/// quadratic and the moments at most cubic, so four coefficients are exact.
struct SectionForceSeries {
  std::array<SectionForces, 4> c;
  SectionForces at(double s) const;
};

/// Whether the element's own span load is part of a displacement field: a static solution
/// carries it (the deflection between the nodes includes the load's local bending), a mode
/// shape or any other field of the nodes alone does not.
enum class SpanLoad { applied, none };

/// A load per length on a line element varying linearly along it, in the element frame:
/// q(s) = mean + halfRise (2 s - 1) (N/m; local x, y, z components), s the fraction of the
/// length from the start node; and a strain imposed uniformly along it (a temperature change:
/// ImposedStrain). Everything an element derives from them is linear in them, so a factored
/// sum of span loads gives the factored sum of their effects.
struct ElementSpanLoad {
  Eigen::Vector3d mean = Eigen::Vector3d::Zero();
  Eigen::Vector3d halfRise = Eigen::Vector3d::Zero();
  /// The imposed strain of the section (a thermal strain; the section's stress follows from
  /// the total strain less this): the axial strain of the axis (alpha dT), then the curvatures
  /// about local y and local z (1/m), each the rate of the section's rotation ry, rz along x,
  /// so the fibre at (y, z) is imposed strain[0] - y strain[2] + z strain[1]. A temperature
  /// that rises by dTy across the depth hy towards +y gives strain[2] = -alpha dTy / hy, one
  /// rising by dTz across hz towards +z strain[1] = alpha dTz / hz.
  Eigen::Vector3d strain = Eigen::Vector3d::Zero();
  bool isZero() const { return mean.isZero() && halfRise.isZero() && strain.isZero(); }
  ElementSpanLoad& operator+=(const ElementSpanLoad& o) {
    mean += o.mean;
    halfRise += o.halfRise;
    strain += o.strain;
    return *this;
  }
  friend ElementSpanLoad operator*(double factor, const ElementSpanLoad& q) {
    return {factor * q.mean, factor * q.halfRise, factor * q.strain};
  }
};

/// The strain a temperature change imposes on a section of its material's alpha (1/K): dT (K)
/// at the centroid, rising linearly through the depth by dTy from the section's lowest to its
/// highest fibre along local y, and by dTz likewise along z (the depths are the extents of the
/// section's fibres). Laid out as ElementSpanLoad::strain. A gradient across a section whose
/// extent is unknown (no fibres) throws std::invalid_argument.
Eigen::Vector3d thermalStrain(const Section& s, double dT, double dTy, double dTz);

/// The normal stress over a section as a linear field of the local coordinates:
/// sigma(y, z) = c + a y + b z with c = N/A, a = -Mz/Iz, b = My/Iy (principal axes; the signs
/// make the stresses' moments on the +x face equal Mz = -int y sigma dA, My = int z sigma dA).
struct FibreStressField {
  double c = 0, a = 0, b = 0;
};
FibreStressField fibreStressField(const Section& s, const SectionForces& f);

/// The largest |sigma| of the field over one fibre (Pa): at a sharp corner |c + a y + b z|; over
/// an arc of radius r about (y, z) the field's extreme on the arc, |c + a y + b z| +
/// r hypot(a, b) when the field's gradient points into the arc.
double fibreNormalStress(const StressFibre& fibre, const FibreStressField& field);

/// Largest |normal stress| over the section (Pa): the largest over its fibres (the corners of
/// an I-section's flanges carry |N|/A + |Mz| cy/Iz + |My| cz/Iy; a circle or tube the resultant
/// moment, |N|/A + R sqrt(My^2 + Mz^2)/I). NaN for a section without fibres.
double maxNormalStress(const Section& s, const SectionForces& f);

class LineElement : public Element {
 public:
  /// The two end nodes (start, end).
  virtual std::array<int, 2> endNodes() const = 0;
  /// Length (m).
  virtual double length() const = 0;
  virtual const Section& section() const = 0;
  /// Rows are the local x, y, z axes in global coordinates.
  virtual Eigen::Matrix3d localAxes() const = 0;
  /// The span load the element carries (zero when none).
  virtual ElementSpanLoad spanLoad() const = 0;
  /// A load per length varying linearly from qStart at the start node to qEnd at the end node
  /// (N/m, global frame) as this element carries it (in its frame).
  virtual ElementSpanLoad spanLoadOf(const Eigen::Vector3d& qStart,
                                     const Eigen::Vector3d& qEnd) const = 0;
  /// Equivalent nodal loads of span load q on this element (global frame, ordered as dofs(),
  /// released rotations condensed); empty when q is zero. load() is this of spanLoad().
  virtual ElementVector loadOf(const ElementSpanLoad& q) const = 0;
  /// Resultants along the element from its nodal displacements u (global frame, ordered as
  /// dofs()) under span load q (a load case's, in place of the element's own).
  virtual SectionForceSeries sectionForceSeries(const ElementVector& u,
                                                const ElementSpanLoad& q) const = 0;
  /// The same under the element's own span load.
  SectionForceSeries sectionForceSeries(const ElementVector& u) const {
    return sectionForceSeries(u, spanLoad());
  }
  /// Resultants at fraction s in [0, 1] of the length (sectionForceSeries at s).
  SectionForces sectionForces(const ElementVector& u, double s) const {
    return sectionForceSeries(u).at(s);
  }
  /// Displacements (global frame: ux uy uz (m), rx ry rz (rad)) at fraction s of the length,
  /// from the nodal displacements u (ordered as dofs()) by the element's own interpolation,
  /// with span load q's share (zero: the nodes' field alone). A released end (a hinge) has its
  /// own rotation, recovered from the element's condensation, not its node's.
  virtual std::array<double, kDofKinds> displacementAt(const ElementVector& u, double s,
                                                       const ElementSpanLoad& q) const = 0;
  /// The same with the element's own span load when `load` is applied, none otherwise.
  std::array<double, kDofKinds> displacementAt(const ElementVector& u, double s,
                                               SpanLoad load) const {
    return displacementAt(u, s, load == SpanLoad::applied ? spanLoad() : ElementSpanLoad{});
  }
  /// Whether some rotation of end 0 (start) or 1 (end) is released (a hinge).
  virtual bool releases(int end) const = 0;

  const LineElement* asLineElement() const final { return this; }
};

/// The element as a line element, or null (springs, masses, bearings).
inline const LineElement* asLine(const std::unique_ptr<Element>& e) { return e->asLineElement(); }

}  // namespace beamrotor

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

/// Largest |normal stress| over the section's outer fibres (Pa): |N|/A plus bending.
/// Circular and tubular sections bend about the resultant axis: M = sqrt(My^2 + Mz^2).
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
  /// Resultants at fraction s in [0, 1] of the length, from the element's nodal
  /// displacements u (global frame, ordered as dofs()).
  virtual SectionForces sectionForces(const ElementVector& u, double s) const = 0;
};

}  // namespace beamrotor

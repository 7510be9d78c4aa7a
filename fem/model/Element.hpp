// The element interface: what the assembler and the analyses need from any element.
// An element knows its nodes and the dofs it touches, never a global equation number.
#pragma once

#include <Eigen/Dense>
#include <string>

#include "fem/model/Dof.hpp"

namespace beamrotor {

class LineElement;

/// The largest element: a two-node 3D frame element, 12 dofs.
inline constexpr int kMaxElementDofs = 12;

/// Element matrices live on the stack (no allocation per element while assembling).
using ElementMatrix = Eigen::Matrix<double, Eigen::Dynamic, Eigen::Dynamic, Eigen::ColMajor,
                                    kMaxElementDofs, kMaxElementDofs>;
using ElementVector = Eigen::Matrix<double, Eigen::Dynamic, 1, Eigen::ColMajor, kMaxElementDofs, 1>;

/// Any element: beam, spring, point mass, contact. Every matrix and vector is in the global
/// frame, SI units, rows and columns ordered as dofs().
class Element {
 public:
  virtual ~Element() = default;

  /// The dofs this element couples, in the order of its matrices.
  virtual ElementDofs dofs() const = 0;
  /// This element as a line element (LineElement.hpp), or null: one virtual call where a
  /// dynamic_cast costs 40 ns (0.05 s a pass over 10^6 beams).
  virtual const LineElement* asLineElement() const { return nullptr; }
  /// Stiffness (N/m, N m/rad, ...).
  virtual ElementMatrix stiffness() const = 0;
  /// True when stiffness() is symmetric whatever the element's data (beams, springs, point
  /// masses): a matrix assembled from such elements alone is symmetric by construction.
  virtual bool symmetricStiffness() const { return true; }
  /// Mass (kg, kg m^2); an empty (0 x 0) matrix when the element has none.
  virtual ElementMatrix mass() const { return {}; }
  /// Viscous damping (N s/m ...); empty when none.
  virtual ElementMatrix damping() const { return {}; }
  /// Gyroscopic matrix per unit spin speed (multiply by Omega in rad/s); empty when none.
  virtual ElementMatrix gyroscopic() const { return {}; }
  /// Geometric (initial-stress) stiffness of the section forces that the displacement state u
  /// (ordered as dofs()) puts in the element: the change of the nodal forces with the
  /// displacements that the element's axial force causes by acting through its rotation
  /// (N/m, ...). Compression softens, tension stiffens. Empty when the element has none.
  virtual ElementMatrix geometricStiffness(const ElementVector& u) const { return {}; }
  /// Equivalent nodal loads of the loads the element carries (distributed load, self-weight);
  /// empty when none.
  virtual ElementVector load() const { return {}; }
  /// A short kind name for messages and output, e.g. "beam-eb", "spring".
  virtual std::string kind() const = 0;
  /// True when `other` has this element's matrices of every kind and its load, each for its
  /// own dofs: another element of a uniform segment (the same type, properties, length,
  /// orientation, releases and span load; other nodes). A pass over the elements computes
  /// such a quantity once for a run of them (ReusedForEqual, fem/assembly/Assembly.hpp).
  /// False unless an element type knows better.
  virtual bool sameMatricesAs(const Element& other) const { return false; }

  /// Nodal forces the element exerts against its nodes' displacement u (ordered as dofs()):
  /// K u - f_load. Summed over elements these give internal forces and support reactions.
  ElementVector endForces(const ElementVector& u) const;
};

/// The same from an element's stiffness K and load (empty when none), computed once for a run
/// of equal elements (ReusedForEqual, fem/assembly/Assembly.hpp).
ElementVector endForces(const ElementMatrix& K, const ElementVector& load, const ElementVector& u);

}  // namespace beamrotor

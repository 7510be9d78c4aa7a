// The free-free matrices of a rotor model for the equations of motion at spin speed Omega
//   M q'' + (C(Omega) + Omega G) q' + K(Omega) q = F      (SI units, global frame),
// q ordered as DofMap's free dofs. M and G are assembled once; K and C once plus the
// speed-dependent elements (bearings), which are re-evaluated per speed by adding into the
// same sparsity pattern. Every matrix here shares one pattern, so sums of them keep it and a
// sparse factorisation's symbolic analysis can be reused across speeds.
#pragma once

#include <algorithm>
#include <complex>
#include <vector>

#include "fem/assembly/Assembly.hpp"
#include "fem/model/DofMap.hpp"
#include "fem/model/Results.hpp"
#include "fem/model/RotorElement.hpp"

namespace beamrotor {

class Model;

/// Damping added to the elements' own. Proportional (Rayleigh), on the fixed frame:
/// C += alpha M + beta K(Omega), K the whole stiffness at that speed, bearings included.
/// Internal (rotating) damping of the shaft, viscous in the material of the beams that spin
/// with it: C += beta_i K_s and, because that damping acts on the strain rate seen in the
/// rotating frame, the circulatory stiffness K += Omega beta_i K_s R (K_s the beams' own
/// stiffness, R the quarter turn (uy, uz, ry, rz) -> (uz, -uy, rz, -ry) at every node; skew
/// for an axisymmetric shaft). On a Jeffcott rotor c_i = beta_i k: m r'' + (c_e + c_i) r' +
/// (k - i Omega c_i) r = 0 with r = uy + i uz, whose forward whirl grows above
/// Omega = omega_n (1 + c_e / c_i) (Genta, Dynamics of Rotating Systems, 2005, sec. 6.3;
/// Friswell et al., Dynamics of Rotating Machines, 2010, sec. 5.4).
struct ProportionalDamping {
  double alpha = 0;     ///< 1/s
  double beta = 0;      ///< s
  double internal = 0;  ///< s: beta_i of the shaft's internal damping
};

class RotorSystem {
 public:
  /// Assembles M, G and the speed-independent parts of K and C. The model must outlive this.
  explicit RotorSystem(const Model& model, ProportionalDamping damping = {});

  const Model& model() const { return model_; }
  const DofMap& dofs() const { return dofs_; }
  /// Number of free dofs (rows of every matrix).
  int size() const { return dofs_.freeCount(); }

  /// Mass (kg, kg m^2), symmetric.
  const SparseMatrix& mass() const { return M_; }
  /// Gyroscopic matrix per unit spin speed (kg m^2), skew-symmetric.
  const SparseMatrix& gyroscopic() const { return G_; }
  /// Stiffness at spin speed Omega (rad/s); non-symmetric with cross-coupled bearings or
  /// internal damping (its circulatory part).
  SparseMatrix stiffness(double speed) const;
  /// Adds cross-coupled stiffness Q (N/m) at `node`'s lateral dofs: K(uy, uz) += Q and
  /// K(uz, uy) -= Q, the force (-Q uz, Q uy) that pushes a forward whirl along its orbit (an
  /// aerodynamic or seal cross-coupling, API 684's added k_xy = Q, k_yx = -Q). Replaces the
  /// coupling set before; a later stiffness() includes it at every speed. Throws
  /// std::invalid_argument when uy or uz of `node` is not a free dof.
  void setCrossCoupling(int node, double q);
  /// Viscous damping at spin speed Omega (rad/s), proportional damping included.
  SparseMatrix damping(double speed) const;
  /// Whether an element's coefficients depend on the motion's frequency
  /// (SpeedDependentElement::dependsOnWhirl).
  bool dependsOnWhirl() const { return whirlDependent_; }
  /// Stiffness and damping as stiffness(speed) and damping(speed), with each whirl-dependent
  /// element at the motion e^{lambda t} (lambda in 1/s): what a mode with eigenvalue lambda
  /// sees. The same as the speed's own without whirl-dependent elements.
  SparseMatrix stiffness(double speed, std::complex<double> lambda) const;
  SparseMatrix damping(double speed, std::complex<double> lambda) const;
  /// Whether free equation eq is a bearing's own dof (SpeedDependentElement::ownDofs, a
  /// tilting pad's tilt), not the rotor's.
  bool isBearingOwn(int eq) const { return !bearingOwn_.empty() && bearingOwn_[std::size_t(eq)]; }
  bool hasBearingOwnDofs() const { return !bearingOwn_.empty(); }
  int bearingOwnCount() const { return int(std::count(bearingOwn_.begin(), bearingOwn_.end(), true)); }
  /// Sizes for the results (factorEntries from the caller's factorisation).
  SystemSize systemSize(double factorEntries) const;

 private:
  /// A speed-dependent element: its matrices at rest (already in K0_, C0_) and the position
  /// in the pattern's value array of each of its entries (-1 for a constrained dof).
  struct SpeedTerm {
    const SpeedDependentElement* element;
    std::vector<int> slots;  // column-major over the element's dofs
    ElementMatrix k0, c0;
  };
  /// A plus the changes (kind at speed minus kind at rest) of the speed-dependent elements,
  /// the whirl-dependent ones at `lambda` when given.
  SparseMatrix atSpeed(const SparseMatrix& A, double speed, bool stiffness,
                       const std::complex<double>* lambda = nullptr) const;
  SparseMatrix stiffnessAt(double speed, const std::complex<double>* lambda) const;
  SparseMatrix dampingAt(double speed, const std::complex<double>* lambda) const;

  /// The beams' own stiffness K_s and K_s R (ProportionalDamping::internal), on the pattern;
  /// empty without internal damping.
  void assembleShaft();

  const Model& model_;
  DofMap dofs_;
  ProportionalDamping proportional_;
  SparseMatrix M_, G_, K0_, C0_;
  SparseMatrix shaft_, circulatory_;  ///< K_s and K_s R when beta_i != 0
  SparseMatrix crossCoupling_;        ///< setCrossCoupling's entries; empty without
  std::vector<SpeedTerm> terms_;
  bool whirlDependent_ = false;
  std::vector<bool> bearingOwn_;  ///< per free equation; empty when no element has own dofs
};

}  // namespace beamrotor

// The free-free matrices of a rotor model for the equations of motion at spin speed Omega
//   M q'' + (C(Omega) + Omega G) q' + K(Omega) q = F      (SI units, global frame),
// q ordered as DofMap's free dofs. M and G are assembled once; K and C once plus the
// speed-dependent elements (bearings), which are re-evaluated per speed by adding into the
// same sparsity pattern. Every matrix here shares one pattern, so sums of them keep it and a
// sparse factorisation's symbolic analysis can be reused across speeds.
#pragma once

#include <vector>

#include "fem/assembly/Assembly.hpp"
#include "fem/model/DofMap.hpp"
#include "fem/model/Results.hpp"
#include "fem/model/RotorElement.hpp"

namespace beamrotor {

class Model;

/// Proportional (Rayleigh) damping added to the elements' own: C += alpha M + beta K(Omega),
/// K the whole stiffness at that speed, bearings included.
struct ProportionalDamping {
  double alpha = 0;  ///< 1/s
  double beta = 0;   ///< s
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
  /// Stiffness at spin speed Omega (rad/s); non-symmetric with cross-coupled bearings.
  SparseMatrix stiffness(double speed) const;
  /// Viscous damping at spin speed Omega (rad/s), proportional damping included.
  SparseMatrix damping(double speed) const;
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
  /// A plus the changes (kind at speed minus kind at rest) of the speed-dependent elements.
  SparseMatrix atSpeed(const SparseMatrix& A, double speed, bool stiffness) const;

  const Model& model_;
  DofMap dofs_;
  ProportionalDamping proportional_;
  SparseMatrix M_, G_, K0_, C0_;
  std::vector<SpeedTerm> terms_;
};

}  // namespace beamrotor

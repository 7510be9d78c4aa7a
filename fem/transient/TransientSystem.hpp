// The semi-discrete system the time-stepping schemes advance: the free-free blocks of K, M and
// C (elements' dampers plus Rayleigh damping) and the force on the free dofs as a function of
// time (the model's loads, the time loads, and what prescribed support motion pushes onto the
// free dofs through the coupling blocks K_FC, C_FC, M_FC).
#pragma once

#include <utility>
#include <vector>

#include "fem/assembly/Assembly.hpp"
#include "fem/model/Model.hpp"
#include "fem/model/Results.hpp"
#include "fem/transient/Transient.hpp"

namespace beamrotor {

/// The state at time t on the free dofs (DofMap's free numbering): m or rad, per s, per s^2.
struct TransientState {
  double t = 0;
  Eigen::VectorXd u, v, a;
};

/// a = M^-1 r, with a = 0 at massless dofs (empty rows and columns of M): see
/// TransientSystem::initialAcceleration. Throws SolveError naming `analysis` when M is singular
/// otherwise.
Eigen::VectorXd accelerationOf(const SparseMatrix& M, Eigen::VectorXd r, const char* analysis);

class TransientSystem {
 public:
  /// Numbers the dofs, assembles K, M, C and the load patterns. Throws std::invalid_argument
  /// for a load or support motion on a dof that is absent (or, for motion, not supported).
  TransientSystem(const Model& model, const TransientOptions& options);

  const Model& model() const { return model_; }
  const DofMap& dofs() const { return dofs_; }
  int size() const { return dofs_.freeCount(); }
  const SparseMatrix& stiffness() const { return K_; }
  const SparseMatrix& mass() const { return M_; }
  const SparseMatrix& damping() const { return C_; }
  bool damped() const { return damped_; }

  /// External force on the free dofs at time t (N, N m), written into f (resized).
  void force(double t, Eigen::VectorXd& f) const;

  /// The prescribed value at constrained equation eq and time t: displacement (derivative 0),
  /// velocity (1) or acceleration (2).
  double supportValue(int eq, double t, int derivative) const;

  /// Free-length vector of a per-node field (zero when the field is empty). Throws
  /// std::invalid_argument when its size does not match the model.
  Eigen::VectorXd freeVector(const NodalField& field, const char* what) const;

  /// The per-node displacement field at time t from the free displacements (supports at their
  /// prescribed values).
  NodalField nodalField(const Eigen::VectorXd& uFree, double t) const;

  /// a = M^-1 (f(t) - C v - K u) for the state s. Massless dofs (zero row and column of M,
  /// e.g. beam rotations with lumped mass and no rotary inertia) get a = 0: their motion follows
  /// from equilibrium, which the implicit schemes enforce at every step anyway. Throws
  /// SolveError when M is singular otherwise.
  Eigen::VectorXd initialAcceleration(const TransientState& s) const;

 private:
  /// nf x nc block coupling free rows to constrained columns, one matrix kind.
  SparseMatrix couplingBlock(MatrixKind kind) const;

  const Model& model_;
  DofMap dofs_;
  SparseMatrix K_, M_, C_;
  bool damped_ = false;

  Eigen::VectorXd modelLoad_;  // free part of the model's own loads
  TimeFunction modelLoadFactor_;
  struct Pattern {
    std::vector<std::pair<int, double>> entries;  // (free equation, value)
    TimeFunction factor;
  };
  std::vector<Pattern> timeLoads_;

  // Support motion: constant prescribed values push -K_FC u_C; moving ones add the velocity
  // and acceleration terms, evaluated at every call.
  Eigen::VectorXd staticPush_;    // free-length, -K_FC u_C for constant values
  Eigen::VectorXd uConstrained_;  // constrained-length constant prescribed values
  std::vector<std::pair<int, SupportMotion>> motions_;  // (constrained index, motion)
  SparseMatrix Kfc_, Cfc_, Mfc_;
};

}  // namespace beamrotor

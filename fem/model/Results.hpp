// Results of the analyses as plain values; writers read these plus the model's nodes.
#pragma once

#include <Eigen/Dense>
#include <optional>
#include <string>
#include <vector>

#include "fem/model/Dof.hpp"

namespace beamrotor {

/// One value per node and dof kind (rows: nodes; columns: ux uy uz rx ry rz, global frame).
/// Dofs the model does not carry are zero.
using NodalField = Eigen::Matrix<double, Eigen::Dynamic, kDofKinds, Eigen::RowMajor>;

/// Wall-clock seconds spent in each stage of a linear solve.
struct SolveTimings {
  double assembly = 0;  ///< assembling K (and M) and the load vector
  double factor = 0;    ///< sparse factorisation (symbolic + numeric)
  double solve = 0;     ///< triangular solves / eigen iterations
  double total = 0;     ///< everything, including recovery
};

/// Size of the discrete system.
struct SystemSize {
  int nodes = 0;
  int elements = 0;
  int dofs = 0;  ///< all dofs, free and constrained
  int freeDofs = 0;
  long long nonzeros = 0;    ///< stored entries of the free-free stiffness block
  double factorEntries = 0;  ///< entries of the factor(s) (fill-in)
};

/// One reaction component of a named support (N or N m, global frame).
struct ReactionComponent {
  std::string support;
  int node = -1;
  Dof dof = Dof::ux;
  double value = 0;
};

/// The settled state of one contact constraint.
struct ContactState {
  std::string name;
  int node = -1;
  Dof dof = Dof::uy;
  bool active = false;  ///< the dof rests on a bound
  double value = 0;     ///< the dof's value (m or rad)
  double bound = 0;     ///< the bound it rests on, or the nearest one when open
  double gap = 0;       ///< distance to the nearest bound (0 when active)
  double force = 0;     ///< force or moment the stop exerts (N or N m; 0 when open)
};

/// The settled state of one tension-only or compression-only member (fem/static/OneWayMembers).
struct OneWayMemberState {
  std::string name;
  bool slack = false;     ///< out of action: a tension-only member shortened, or the reverse
  double force = 0;       ///< axial force N (tension positive); 0 when slack
  double elongation = 0;  ///< change of its end nodes' distance (m)
};

/// The rotations on the two sides of a node: the rotation vector (global frame, rad) of the
/// line-element end there, `left` of the element ending at the node, `right` of the one
/// starting there (empty where there is none). At a hinge they differ, and the node itself may
/// carry no rotation at all.
struct SideRotations {
  int node = -1;
  std::optional<Eigen::Vector3d> left, right;
};

struct StaticResult {
  NodalField displacement;                   ///< m and rad
  std::vector<ReactionComponent> reactions;  ///< every constrained dof, in support order
  std::vector<ContactState> contacts;        ///< settled contact states, in model order
  std::vector<OneWayMemberState> oneWayMembers;  ///< tension- or compression-only members
  /// The force each named element (Model::namedElements: springs, bearings) exerts on the
  /// structure at its first node, per dof it acts on there: as a support's reaction.
  std::vector<ReactionComponent> elementForces;
  std::vector<SideRotations> hinges;         ///< at every node with a released beam end
  int activeSetIterations = 0;               ///< linear solves the contact loop needed
  double rcond = 0;     ///< reciprocal condition estimate of the scaled system D^-1/2 K D^-1/2
  double roundOff = 0;  ///< measured relative error of the solution (extended-precision residual)
  std::string solver;                        ///< the direct method used (LinearSolver)
  SystemSize size;
  SolveTimings time;

  /// Sum of the reaction components of one support along one dof kind; for a name no support
  /// has, the force of the named element (a spring, a bearing) or of the contact so named.
  double reaction(const std::string& support, Dof d) const;
};

/// One vibration mode.
struct Mode {
  double eigenvalue = 0;   ///< omega^2 (rad^2/s^2); exactly 0 for rigid-body modes
  double frequencyHz = 0;  ///< sqrt(eigenvalue) / (2 pi); 0 for rigid-body modes
  /// A zero-energy motion of the structure (a rigid-body mode or a mechanism): K's null space.
  bool rigidBody = false;
  NodalField shape;        ///< mass-normalised (phi^T M phi = 1)
  /// Participation factor r_k' M phi (kg^0.5, signed as the shape) of rigid translation r_k
  /// along ux, uy, uz; its square is the effective modal mass.
  std::array<double, 3> participation{};
  /// Effective modal mass (kg) for rigid translation along ux, uy, uz.
  std::array<double, 3> effectiveMass{};
  /// Share of the mode's kinetic energy carried by each dof kind (sums to 1).
  std::array<double, kDofKinds> energyShare{};
  /// A few words to recognise the mode by, e.g. "bending uy", "axial ux", "torsion rx".
  std::string description;
};

struct ModalResult {
  std::vector<Mode> modes;  ///< ascending frequency
  double shift = 0;         ///< the shift used (rad^2/s^2)
  /// Mass (kg) moving with a rigid translation along ux, uy, uz, for effective-mass ratios.
  std::array<double, 3> totalMass{};
  SystemSize size;
  SolveTimings time;
  std::vector<std::string> warnings;  ///< e.g. modes a Sturm count says were skipped
};

}  // namespace beamrotor

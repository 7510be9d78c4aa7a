// Two-node straight beam: Euler-Bernoulli, Timoshenko (interdependent interpolation, free of
// shear locking) and the naive equal-order linear Timoshenko element kept to show locking.
// One class serves planar frames (ux, uy, rz), 3D frames (all six) and lateral rotor models
// (uy, uz, ry, rz): the 12 x 12 local matrices are built once and only the dofs the model
// carries are kept, which is exact because those dofs do not couple to the others.
#pragma once

#include <array>
#include <cstdint>
#include <memory>
#include <vector>

#include "fem/model/LineElement.hpp"

namespace beamrotor {

enum class BeamTheory {
  /// Cubic Hermite bending, no shear strain.
  eulerBernoulli,
  /// Interdependent interpolation (cubic deflection, quadratic rotation tied to it through the
  /// shear parameter Phi = 12 E I / (kappa G A L^2)); exact for end-loaded static beams.
  timoshenko,
  /// Linear deflection and rotation, shear integrated exactly (2 Gauss points): the textbook
  /// element that LOCKS as the beam gets slender. For demonstrations and tests only.
  timoshenkoLinearFullIntegration,
  /// The same element with 1-point shear integration: the classical remedy for locking.
  timoshenkoLinearReducedIntegration,
};

enum class MassModel { consistent, lumped };

struct BeamOptions {
  BeamTheory theory = BeamTheory::eulerBernoulli;
  MassModel mass = MassModel::consistent;
  /// Include the rotary inertia of the cross-sections (rho I per length) in bending.
  bool rotaryInertia = false;
  bool operator==(const BeamOptions&) const = default;
};

class Beam : public LineElement {
 public:
  /// Beam from node n1 at x1 to node n2 at x2 carrying the dofs of `carried`.
  /// zHint: a global direction in the local x-z plane (default global z, so a beam in the
  /// x-y plane bends in that plane about local z = global z).
  Beam(int n1, const Eigen::Vector3d& x1, int n2, const Eigen::Vector3d& x2,
       std::shared_ptr<const Section> section, DofSet carried, BeamOptions options = {},
       const Eigen::Vector3d& zHint = Eigen::Vector3d::UnitZ());
  /// Beam from node n1 to node n2 whose length and axis direction the caller knows exactly
  /// (a mesh builder: segment length / element count, the line's direction), so neither is
  /// a difference of node coordinates, which far from the origin loses digits (at 9e4 m,
  /// about 1e-11 m of a 0.06 m element). `direction` need not be normalised.
  Beam(int n1, int n2, const Eigen::Vector3d& direction, double length,
       std::shared_ptr<const Section> section, DofSet carried, BeamOptions options = {},
       const Eigen::Vector3d& zHint = Eigen::Vector3d::UnitZ());

  /// Hinge: the moment about local rotation axis `rotation` (rx, ry or rz) vanishes at end
  /// 0 (start) or 1 (end). The released rotation is condensed out of the element.
  void release(int end, Dof rotation);
  /// A slack member (a tension-only rod that shortened, a compression-only strut that
  /// lifted off, fem/static/OneWayMembers): stiffness, loads and resultants all zero; its
  /// mass and geometry stay.
  void setSlack(bool slack);
  bool slack() const { return p_->slack; }
  /// Uniform load per length (N/m), global frame; replaces any earlier one.
  void setDistributedLoad(const Eigen::Vector3d& q);
  /// Load per length varying linearly from qStart at the start node to qEnd at the end node
  /// (N/m, global frame); replaces any earlier one.
  void setDistributedLoad(const Eigen::Vector3d& qStart, const Eigen::Vector3d& qEnd);
  /// A strain imposed along the whole beam (a temperature change, thermalStrain), laid out as
  /// ElementSpanLoad::strain; replaces any earlier one.
  void setImposedStrain(const Eigen::Vector3d& strain);

  ElementDofs dofs() const override { return {nodes_, p_->dofCodes.data(), p_->count}; }
  ElementMatrix stiffness() const override;
  ElementMatrix mass() const override;
  /// Gyroscopic matrix per unit spin speed (kg m^2: N m per rad/s of spin and rad/s of tilt
  /// rate), global frame, ordered as dofs(), for spin about the local +x axis. Comes from the
  /// same rho I as the rotary inertia, so a beam without rotary inertia (or one that carries
  /// only one bending rotation, e.g. a planar beam) has none: empty matrix.
  ElementMatrix gyroscopic() const override;
  /// A prescribed axial force (N, tension positive) added to the one a state gives: a lateral
  /// rotor model carries no axial dof, so its shaft's axial load is given, not solved for.
  void setAxialPreload(double N);
  /// Geometric stiffness of the axial force the state u puts in the beam (linear along it
  /// under an axial span load), global frame, releases condensed as in mass().
  ElementMatrix geometricStiffness(const ElementVector& u) const override;
  ElementVector load() const override { return loadOf(spanLoad()); }
  ElementSpanLoad spanLoad() const override { return {p_->qMean, p_->qHalfRise, p_->strain}; }
  ElementSpanLoad spanLoadOf(const Eigen::Vector3d& qStart,
                             const Eigen::Vector3d& qEnd) const override;
  ElementVector loadOf(const ElementSpanLoad& q) const override;
  std::string kind() const override;
  /// Same section object, carried dofs, options, length, axes, preload, span load and
  /// releases.
  bool sameMatricesAs(const Element& other) const override;

  std::array<int, 2> endNodes() const override { return nodes_; }
  double length() const override { return p_->L; }
  const Section& section() const override { return *p_->section; }
  Eigen::Matrix3d localAxes() const override { return p_->R; }
  using LineElement::displacementAt;
  using LineElement::sectionForceSeries;
  SectionForceSeries sectionForceSeries(const ElementVector& u,
                                        const ElementSpanLoad& q) const override;
  /// Axial displacement and twist linear (plus the bar's share of an axial span load);
  /// deflections and section rotations by the theory's own shape functions (Hermite cubics,
  /// the interdependent interpolation, or linear), which are exact for end-loaded elements,
  /// plus with `load` the clamped-clamped solution of the linear span load (exact for
  /// Euler-Bernoulli and interdependent Timoshenko elements; not added to the linear ones).
  std::array<double, kDofKinds> displacementAt(const ElementVector& u, double s,
                                               const ElementSpanLoad& q) const override;
  bool releases(int end) const override;
  const BeamOptions& options() const { return p_->options; }

  using Matrix12 = Eigen::Matrix<double, 12, 12>;
  using Vector12 = Eigen::Matrix<double, 12, 1>;
  /// Local-frame matrices before releases (local dofs u v w rx ry rz at each end).
  Matrix12 localStiffness() const;
  Matrix12 localMass() const;
  /// Local gyroscopic matrix (skew-symmetric), local dofs as localMass(); zero without
  /// rotary inertia.
  Matrix12 localGyroscopic() const;
  /// Equivalent nodal loads of span load q (local dofs, before releases), the negated forces
  /// that hold the element's ends fixed under it; localLoad() of its own.
  Vector12 localLoad(const ElementSpanLoad& q) const;
  Vector12 localLoad() const { return localLoad(spanLoad()); }
  /// Local geometric stiffness for an axial force varying linearly from N0 at the start to N1
  /// at the end (N, tension positive), local dofs as localStiffness():
  ///   bending, each plane: int N(x) v'^T v' dx with the deflection interpolation v of the
  ///   element's own theory (Hermite cubics; the interdependent Timoshenko shapes, whose slope
  ///   includes the shear strain, which gives Engesser's reduced buckling load; linear);
  ///   torsion: the Wagner term int N (Ip / A) rx'^T rx' dx of a doubly symmetric section
  ///   (shear centre at the centroid): McGuire, Gallagher and Ziemian, Matrix Structural
  ///   Analysis, 2nd ed. (2000), sec. 9.3. Terms of the end moments (lateral-torsional
  ///   buckling) and warping are not included.
  Matrix12 localGeometricStiffness(double N0, double N1) const;

 private:
  /// Applies the end releases to local K and, when given, M and the load (static
  /// condensation; K is needed for all three).
  void condense(Matrix12& K, Matrix12* M, Vector12* f) const;
  /// Shear parameters Phi = 12 E I / (kappa G A L^2) for bending about local z and local y;
  /// zero unless the theory is the interdependent-interpolation Timoshenko element.
  std::array<double, 2> shearParameters() const;
  /// Global 12 x 12 -> the carried dofs only.
  ElementMatrix toCarried(const Matrix12& local) const;
  Vector12 toLocal(const ElementVector& u) const;
  /// The 12 local end displacements with every released rotation recovered from the
  /// condensation: the released rows of K l = f (no end moment there) give
  /// Kbb l_b = f_b - Kba l_a, f the fixed-end forces of span load q.
  Vector12 localEndDisplacements(const ElementVector& u, const ElementSpanLoad& q) const;

  /// Everything a beam has but its nodes. The beams of a uniform run (a line's segment) share
  /// one, so each holds 32 bytes, where a beam with its own took 320 (a planar line of 10^6
  /// beams: 290 MB less, and passes over the beams read a tenth of the memory).
  struct Properties {
    std::shared_ptr<const Section> section;
    DofSet carried;
    BeamOptions options;
    double L = 0;
    Eigen::Matrix3d R;        // rows: local axes in global coordinates
    double axialPreload = 0;  // N, tension positive; see setAxialPreload
    // The span load in the local frame: its mean and half the change from start to end, so
    // q(s) = qMean + qHalfRise (2 s - 1).
    Eigen::Vector3d qMean = Eigen::Vector3d::Zero();
    Eigen::Vector3d qHalfRise = Eigen::Vector3d::Zero();
    Eigen::Vector3d strain = Eigen::Vector3d::Zero();  // imposed; see ElementSpanLoad::strain
    std::vector<int> released;  // local indices 0..11 of released rotations
    bool slack = false;         // see setSlack
    // The dofs kept (elementDofCode), from carried, released and R (numberDofs).
    std::array<std::uint8_t, 12> dofCodes{};
    std::uint8_t count = 0;

    /// The carried dofs, less a released rotation about a global axis, in dofCodes.
    void numberDofs();
    bool operator==(const Properties&) const = default;
  };
  /// Takes p, numbering its dofs; when it equals the properties this thread made last, this
  /// beam shares those (a mesh builder makes a segment's beams one after another, so they
  /// all share one, and so do their span loads when set one by one).
  void setProperties(Properties p);

  std::array<int, 2> nodes_;
  std::shared_ptr<const Properties> p_;
};

}  // namespace beamrotor

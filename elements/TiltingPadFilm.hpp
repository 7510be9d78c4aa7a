// One pad of a tilting-pad bearing with the pad's tilt kept as a degree of freedom of its own
// (the full model of the bearing: nothing condensed, no whirl frequency assumed).
//
// The pad's film (elements/TiltingPadBearing.hpp) depends on the journal's motion relative to
// the pad's centre of curvature only: with u the journal's (uy, uz), delta the pad's tilt about
// its pivot (rad, positive in the sense of rotation) and Q the pad's axes (e_k towards the
// pivot, t_k a quarter turn on) in the global (y, z) axes, that motion in pad axes is
// w = Q^T u - R delta t (t = (0, 1), R the journal's radius). The film's force on the journal
// is -Q Z_k w and its moment on the pad about the pivot R t^T Z_k w, so over (uy, uz, delta)
//   K = B K_k B^T,  C = B C_k B^T,  B = [Q; -R t^T]   (3 x 2),
// K_k, C_k the film's dimensional coefficient matrices in pad axes (Lund 1964; Allaire,
// Parsell and Barrett, Wear 72, 1981). The pad's polar moment of inertia about its pivot I_p
// (kg m^2) sits on delta. Eliminating delta from K + s C + s^2 M at s gives the pad's share of
// the condensed coefficients Z_k' (tiltingPadCoefficientsAt) when I_p = 0: the full model's
// eigenvalues are then exactly the fixed points of the per-mode iteration.
//
// Between the table's speeds K_k and C_k are linear in the speed (the end points held), so the
// bearing's full model is exact at each table speed. The tilt is the rx dof of a node of the
// pad's own (at the journal's position); kind "tilting-pad film".
#pragma once

#include <memory>
#include <optional>
#include <vector>

#include "elements/TiltingPadBearing.hpp"
#include "fem/model/RotorElement.hpp"

namespace beamrotor {

class TiltingPadFilm : public SpeedDependentElement {
 public:
  /// Pad `pad` (index into each point's pads) of the operating points `points` (ascending
  /// speeds), between `journal`'s uy, uz and `padNode`'s rx; the bearing's axes turned by
  /// `loadAngle` (rad) about +x; `inertia` the pad's polar moment about its pivot (kg m^2,
  /// >= 0). At a point where the journal has left the pad nothing couples it; its tilt keeps
  /// the nearest loaded point's own stiffness and damping (none for a pad loaded at no point:
  /// the nonlinear run-up's pads, whose films act instead). Throws std::invalid_argument for
  /// no points.
  TiltingPadFilm(int journal, int padNode, std::shared_ptr<const std::vector<TiltingPadPoint>> points,
                 int pad, double loadAngle, double inertia);

  ElementDofs dofs() const override;
  ElementMatrix stiffnessAt(double speed) const override;
  ElementMatrix dampingAt(double speed) const override;
  ElementMatrix mass() const override;
  std::string kind() const override { return "tilting-pad film"; }
  int ownDofs() const override { return 1; }  ///< the pad's tilt

  int journal() const { return journal_; }
  int padNode() const { return padNode_; }
  int pad() const { return pad_; }
  /// The pad's share of the bearing's synchronous coefficients at `speed` (its tilt
  /// condensed at whirl = spin, massless), global axes, linear between table speeds.
  BearingCoefficients synchronousAt(double speed) const;

 private:
  /// B K_k B^T (stiffness) or B C_k B^T at table point i.
  ElementMatrix filmAt(std::size_t i, bool damping) const;
  ElementMatrix interpolated(double speed, bool damping) const;

  int journal_, padNode_;
  std::shared_ptr<const std::vector<TiltingPadPoint>> points_;
  std::vector<double> speeds_;
  /// Per point, the nearest one loading the pad (none: the pad is loaded at no point)
  std::vector<std::optional<std::size_t>> nearestLoaded_;
  int pad_;
  double loadAngle_, inertia_;
};

/// Whether pad `pad` carries a film at one of `points` at least: the pads the full model keeps.
bool padEverLoaded(const std::vector<TiltingPadPoint>& points, int pad);

}  // namespace beamrotor

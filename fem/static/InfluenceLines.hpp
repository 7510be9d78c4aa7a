// Influence lines of linear static quantities for a unit load moving along a path of
// Euler-Bernoulli line elements, exact everywhere on the path, not only at its nodes.
//
// A point load at fraction xi of an element acts on the nodes as its consistent nodal loads
// (Hermite cubics across the element, linear along it), which give the exact nodal
// displacements and so the exact reactions and node values; the element's own share is the
// clamped beam's response to the load, which only a resultant read inside that element sees.
// So with one factorisation of K, one right-hand side per (path node, loaded dof) gives every
// quantity's value for a load anywhere: a cubic in the position on each element, plus the
// clamped part (piecewise cubic) for a resultant read at an end of the loaded element.
#pragma once

#include <functional>
#include <optional>
#include <vector>

#include <Eigen/Core>

#include "fem/assembly/MemberExtrema.hpp"
#include "fem/assembly/Polynomial.hpp"
#include "fem/model/LineElement.hpp"
#include "fem/model/Model.hpp"
#include "fem/model/Results.hpp"
#include "fem/static/Static.hpp"

namespace beamrotor {

/// One element of a path, traversed from its start node (or, reversed, from its end node).
struct PathElement {
  int element = -1;  ///< index into model.elements(); a line element
  bool reversed = false;
};

/// A quantity linear in the loads, as an influence line needs it: its value in a static
/// solution under nodal loads only, and, when it is a resultant read at an end of one element,
/// that element, the end and the component, so that a load inside that element adds its
/// clamped share.
struct InfluenceQuantity {
  std::function<double(const StaticResult&)> value;
  int element = -1;  ///< the element the resultant is read in; -1 for any other quantity
  int end = 0;       ///< 0: at its start node, 1: at its end node
  ForceComponent component = ForceComponent::Mz;
};

/// A quantity's value for a unit load at distance s along the path: on each piece between
/// consecutive breaks (the path's nodes) a polynomial in t = (s - breaks[p]) / (breaks[p+1] -
/// breaks[p]) in [0, 1]. Where the line jumps (a shear force at the place it is read) a break
/// has two values, the limits of its two pieces.
struct InfluenceLine {
  std::vector<double> breaks;      ///< from 0 to the path's length, ascending
  std::vector<Polynomial> pieces;  ///< one fewer than breaks
  /// The piece holding s (0 <= s <= length), the later one at a break.
  std::size_t pieceAt(double s) const;
  /// The value at s, read in pieceAt(s).
  double at(double s) const;
  double length() const { return breaks.back(); }
};

/// The unit loads of a path, solved with one factorisation of K: one static solution per path
/// node and global dof a load on the path acts on, and, per path element, how a unit load at
/// fraction xi of it shares among those solutions (polynomials in xi from the element's own
/// start, whichever way the path crosses it).
struct PathUnitLoads {
  std::vector<PathElement> path;
  std::vector<const LineElement*> lines;  ///< the path's elements, in path order
  Eigen::Vector3d direction;              ///< of the unit load (normalised)
  std::vector<StaticResult> solved;       ///< one per loaded dof
  /// The model's own loads on the same factorisation, when asked for (the dead load the
  /// train crosses).
  std::optional<StaticResult> modelLoads;
  std::vector<std::vector<std::pair<int, Polynomial>>> shares;  ///< per path element: (solved index, share)
  double length() const;                  ///< of the path (m)
};

/// Solves the unit loads of `path` for a load along `direction`, and with `withModelLoads` the
/// model's own loads as one more right-hand side. Throws std::invalid_argument when the path is
/// empty or broken, an element is not a line element or a loaded dof is one no element
/// carries; throws as solveLoadings does.
PathUnitLoads solvePathUnitLoads(const Model& model, const std::vector<PathElement>& path,
                                 const Eigen::Vector3d& direction,
                                 const StaticOptions& options = {}, bool withModelLoads = false);

/// A quantity's influence line from its value under each unit load (`unitValues[c]` in
/// `units.solved[c]`); a resultant read at end `end` of element `element` (-1: none) adds the
/// clamped share of a load inside that element.
InfluenceLine influenceLineOf(const PathUnitLoads& units, const std::vector<double>& unitValues,
                              int element = -1, int end = 0,
                              ForceComponent component = ForceComponent::Mz);

/// The influence lines of `quantities` for a unit load along global `direction` (normalised
/// here) moving along `path` (consecutive elements share a node). Throws
/// std::invalid_argument when the path is empty or broken, an element is not a line element
/// or a loaded dof is one no element carries; throws as solveLoadings does.
std::vector<InfluenceLine> influenceLines(const Model& model, const std::vector<PathElement>& path,
                                          const Eigen::Vector3d& direction,
                                          const std::vector<InfluenceQuantity>& quantities,
                                          const StaticOptions& options = {});

}  // namespace beamrotor

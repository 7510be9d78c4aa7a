#include "fem/static/InfluenceLines.hpp"

#include <algorithm>
#include <cmath>
#include <map>
#include <stdexcept>
#include <string>
#include <utility>

#include <Eigen/Geometry>

#include "fem/model/DofMap.hpp"
#include "fem/model/LineElement.hpp"
#include "fem/model/Loading.hpp"

namespace beamrotor {

namespace {

/// Below this (of a unit direction) a load component is round-off of the path's geometry.
constexpr double kNegligibleComponent = 1e-12;

/// The Hermite cubics in xi (the fraction from the element's start) for length L: the share of
/// a unit transverse point load taken by the start node's force, start moment, end force and
/// end moment; and the linear shares of an axial one.
struct Shares {
  Polynomial startForce, startMoment, endForce, endMoment, startAxial, endAxial;
};
Shares sharesFor(double L) {
  return {{1, 0, -3, 2},  {0, L, -2 * L, L}, {0, 0, 3, -2},
          {0, 0, -L, L},  {1, -1},           {0, 1}};
}

/// A path node's unit load along one global dof: the right-hand side it is solved as.
using LoadedDof = std::pair<int, Dof>;

/// The consistent nodal loads of a unit load along `direction` at fraction xi of `line`, as
/// polynomials in xi, by the node and dof they act on.
std::vector<std::pair<LoadedDof, Polynomial>> nodalShares(const LineElement& line,
                                                          const Eigen::Vector3d& direction) {
  const auto [start, end] = line.endNodes();
  const Eigen::Vector3d tangent = line.localAxes().row(0).transpose();
  const Eigen::Vector3d along = direction.dot(tangent) * tangent;
  const Eigen::Vector3d across = direction - along;
  const Eigen::Vector3d moment = tangent.cross(across);
  const Shares h = sharesFor(line.length());
  std::vector<std::pair<LoadedDof, Polynomial>> out;
  const auto add = [&](int node, Dof d, double weight, const Polynomial& share) {
    if (std::abs(weight) > kNegligibleComponent)
      out.push_back({{node, d}, combination(weight, share, 0, {})});
  };
  const std::array<Dof, 3> forces{Dof::ux, Dof::uy, Dof::uz}, moments{Dof::rx, Dof::ry, Dof::rz};
  for (int c = 0; c < 3; ++c) {
    add(start, forces[c], along[c], h.startAxial);
    add(start, forces[c], across[c], h.startForce);
    add(end, forces[c], along[c], h.endAxial);
    add(end, forces[c], across[c], h.endForce);
    add(start, moments[c], moment[c], h.startMoment);
    add(end, moments[c], moment[c], h.endMoment);
  }
  return out;
}

/// The clamped share of a unit load along `direction` at fraction xi of `line` in its
/// resultant `component` at end `end`, as a polynomial in xi. The element's own recovery of a
/// uniform unit load on the clamped element (zero end displacements) fixes the signs of its
/// resultants; the point load's clamped end forces and moments relate to the uniform load's
/// as the closed forms do (fixed-end reactions, e.g. Roark's Formulas for Stress and Strain,
/// 8th ed., table 8.1 cases 1c and 2c): a shear R_A = (1-xi)^2 (1+2xi) against L/2, a moment
/// M_A = L xi (1-xi)^2 against L^2/12, an axial force (1-xi) against L/2; mirrored at the end.
Polynomial clampedShare(const LineElement& line, const Eigen::Vector3d& direction, int end,
                        ForceComponent component) {
  const double L = line.length();
  const Eigen::Vector3d local = line.localAxes() * direction;
  const ElementVector still = ElementVector::Zero(line.dofs().size());
  const bool moment = component == ForceComponent::My || component == ForceComponent::Mz;
  const bool axial = component == ForceComponent::N;
  if (component == ForceComponent::T) return {};
  const Shares h = sharesFor(L);
  // Against the uniform load's value at the same end: its shape scaled to 1 there.
  Polynomial shape = moment  ? combination(12 / (L * L), end == 0 ? h.startMoment : h.endMoment,
                                           0, {})
                     : axial ? combination(2 / L, end == 0 ? h.startAxial : h.endAxial, 0, {})
                             : combination(2 / L, end == 0 ? h.startForce : h.endForce, 0, {});
  if (moment && end == 1) shape = combination(-1, shape, 0, {});  // endMoment is -M_B
  double weight = 0;
  for (int k = 0; k < 3; ++k) {
    if (std::abs(local[k]) <= kNegligibleComponent) continue;
    ElementSpanLoad unit;
    unit.mean[k] = 1;
    const SectionForces uniform = line.sectionForceSeries(still, unit).at(end);
    weight += local[k] * componentOf(uniform, component);
  }
  return combination(weight, shape, 0, {});
}

}  // namespace

std::size_t InfluenceLine::pieceAt(double s) const {
  const auto next = std::upper_bound(breaks.begin(), breaks.end(), s);
  const std::size_t p = next == breaks.begin() ? 0 : std::size_t(next - breaks.begin()) - 1;
  return std::min(p, pieces.size() - 1);
}

double InfluenceLine::at(double s) const {
  const std::size_t p = pieceAt(s);
  const double width = breaks[p + 1] - breaks[p];
  return valueAt(pieces[p], (s - breaks[p]) / width);
}

PathUnitLoads solvePathUnitLoads(const Model& model, const std::vector<PathElement>& path,
                                 const Eigen::Vector3d& direction, const StaticOptions& options,
                                 bool withModelLoads) {
  if (path.empty()) throw std::invalid_argument("a moving load needs a path of line elements");
  if (!(direction.norm() > 0))
    throw std::invalid_argument("a moving load needs a direction of nonzero length");
  PathUnitLoads out;
  out.path = path;
  out.direction = direction.normalized();
  int reached = -1;  // the node the path has come to
  for (const PathElement& p : path) {
    const LineElement* line =
        p.element >= 0 && p.element < int(model.elements().size())
            ? asLine(model.elements()[std::size_t(p.element)])
            : nullptr;
    if (!line)
      throw std::invalid_argument("element " + std::to_string(p.element) +
                                  " of the path is not a line element");
    const auto ends = line->endNodes();
    const int from = ends[p.reversed ? 1 : 0];
    if (reached >= 0 && from != reached)
      throw std::invalid_argument("the path breaks at element " + std::to_string(p.element) +
                                  ": it does not start where the one before it ends");
    reached = ends[p.reversed ? 0 : 1];
    out.lines.push_back(line);
  }

  // One right-hand side per path node and dof a load there acts on.
  const DofMap dofs(model);
  std::map<LoadedDof, int> column;
  out.shares.resize(path.size());
  for (std::size_t e = 0; e < path.size(); ++e)
    for (auto& [loaded, share] : nodalShares(*out.lines[e], out.direction)) {
      if (dofs.equation(loaded.first, loaded.second) < 0)
        throw std::invalid_argument("the moving load acts on " +
                                    model.describe({loaded.first, loaded.second}) +
                                    ", which no element carries (give a direction the model "
                                    "can carry)");
      const auto [it, added] = column.try_emplace(loaded, int(column.size()));
      out.shares[e].push_back({it->second, std::move(share)});
    }
  std::vector<Loading> loadings;
  loadings.reserve(column.size());
  std::vector<const Loading*> pointers(column.size());
  for (const auto& [loaded, c] : column) {
    loadings.emplace_back(std::vector<NodalLoad>{{loaded.first, loaded.second, 1.0}},
                          std::vector<std::pair<int, ElementSpanLoad>>{});
    pointers[std::size_t(c)] = &loadings.back();
  }
  if (withModelLoads) pointers.push_back(nullptr);  // null: the model's own loads
  out.solved = solveLoadings(model, pointers, options);
  if (withModelLoads) {
    out.modelLoads = std::move(out.solved.back());
    out.solved.pop_back();
  }
  return out;
}

double PathUnitLoads::length() const {
  double sum = 0;
  for (const LineElement* line : lines) sum += line->length();
  return sum;
}

InfluenceLine influenceLineOf(const PathUnitLoads& units, const std::vector<double>& unitValues,
                              int element, int end, ForceComponent component) {
  InfluenceLine line;
  line.breaks.push_back(0);
  for (std::size_t e = 0; e < units.path.size(); ++e) {
    Polynomial inXi;
    for (const auto& [c, share] : units.shares[e])
      inXi = combination(1, inXi, unitValues[std::size_t(c)], share);
    if (element >= 0 && element == units.path[e].element)
      inXi = combination(1, inXi, 1, clampedShare(*units.lines[e], units.direction, end, component));
    line.pieces.push_back(units.path[e].reversed ? composedWithLine(inXi, 1, -1) : inXi);
    line.breaks.push_back(line.breaks.back() + units.lines[e]->length());
  }
  return line;
}

std::vector<InfluenceLine> influenceLines(const Model& model, const std::vector<PathElement>& path,
                                          const Eigen::Vector3d& direction,
                                          const std::vector<InfluenceQuantity>& quantities,
                                          const StaticOptions& options) {
  const PathUnitLoads units = solvePathUnitLoads(model, path, direction, options);
  std::vector<InfluenceLine> out;
  out.reserve(quantities.size());
  std::vector<double> unitValues(units.solved.size());
  for (const InfluenceQuantity& quantity : quantities) {
    for (std::size_t c = 0; c < units.solved.size(); ++c)
      unitValues[c] = quantity.value(units.solved[c]);
    out.push_back(
        influenceLineOf(units, unitValues, quantity.element, quantity.end, quantity.component));
  }
  return out;
}

}  // namespace beamrotor

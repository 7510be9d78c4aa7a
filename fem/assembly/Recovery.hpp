// Element recovery: what a solved nodal field means along the line elements. Displacements
// between the nodes by each element's own interpolation (with a hinge's own end rotation),
// the rotations on the two sides of a node, and stress resultants and stresses at stations.
#pragma once

#include <optional>
#include <vector>

#include "fem/assembly/Polynomial.hpp"
#include "fem/model/LineElement.hpp"
#include "fem/model/Loading.hpp"
#include "fem/model/Model.hpp"
#include "fem/model/Results.hpp"

namespace beamrotor {

class SolutionPolynomials;

/// One static solution as recovery reads it: the model, its nodal field, the loading it was
/// solved under when that is not the model's own (a load case on the same structure,
/// Loading.hpp; null: the loads the model's elements carry), and, when computed once for it,
/// its polynomials along the line elements (SolutionPolynomials.hpp; null: recovered from the
/// field element by element on each call). Converts from a model and a field, the usual case.
struct LoadedSolution {
  const Model* model = nullptr;
  const NodalField* displacement = nullptr;
  const Loading* loading = nullptr;
  const SolutionPolynomials* polynomials = nullptr;

  LoadedSolution(const Model& m, const NodalField& u, const Loading* l = nullptr,
                 const SolutionPolynomials* p = nullptr)
      : model(&m), displacement(&u), loading(l), polynomials(p) {}
  /// The span load line element `element` carries in this solution.
  ElementSpanLoad spanOn(int element, const LineElement& line) const {
    return loading ? loading->spanOn(element) : line.spanLoad();
  }
  /// Line element `element`'s resultants along it (its span load included).
  SectionForceSeries forceSeries(int element) const;
  /// Line element `element`'s translations ux, uy, uz along it as polynomials in s (its span
  /// load's share included; exact, degree <= 5).
  std::array<Polynomial, 3> translationSeries(int element) const;
  /// Line element `element`'s displacements at fraction s (its span load's share included).
  std::array<double, kDofKinds> displacementAt(int element, double s) const;
};

/// An element's nodal values, ordered as its dofs(), from a nodal field.
ElementVector elementValues(const Element& element, const NodalField& field);

/// Displacements (global frame, ux uy uz (m), rx ry rz (rad)) at fraction s of a line element
/// from a nodal field: LineElement::displacementAt, so exact nodal values at the ends (a
/// released end rotation being the element's own) and the element's interpolation between.
std::array<double, kDofKinds> displacementAlong(const LineElement& element, const NodalField& field,
                                                double s, SpanLoad load);

/// The rotations on the two sides of a node (see SideRotations), each beam end's own.
SideRotations rotationsBeside(const LoadedSolution& solution, int node);

/// The side rotations at every node where a line element releases a rotation (a hinge), in
/// node order.
std::vector<SideRotations> hingeRotations(const LoadedSolution& solution);

/// The force each named element (Model::namedElements) exerts on the structure at its first
/// node, per dof it acts on there: -(K u) of the element's first node's rows (springs and
/// bearings carry no loads of their own).
std::vector<ReactionComponent> namedElementForces(const Model& model, const NodalField& field);

/// Fields at one station of one line element.
struct BeamStation {
  int element = -1;                              ///< index into model.elements()
  double s = 0;                                  ///< fraction of the element's length, 0..1
  Eigen::Vector3d position;                      ///< global coordinates (m)
  std::array<double, kDofKinds> displacement{};  ///< global frame, see displacementAlong
  SectionForces forces;                          ///< local frame, see SectionForces
  double stress = 0;  ///< largest |normal stress| on the outer fibres (Pa)
  double shear = 0;   ///< largest transverse shear stress (Pa), see maxShearStress
};

/// Samples a static solution on every line element at `perElement` + 1 evenly spaced
/// stations (ends included), in element order. Other elements (springs, masses) are skipped.
std::vector<BeamStation> recoverBeamFields(const LoadedSolution& solution, int perElement = 1);

}  // namespace beamrotor

// Samples a solved nodal field along the line elements (beams, shafts): where each station
// lies along the line, the displacements between the nodes and, for statics, the section
// forces and stress. The CSV tables, the charts and results.json's largest stress all read
// these samples, so they agree with one another.
#pragma once

#include <array>
#include <optional>
#include <vector>

#include "fem/model/LineElement.hpp"
#include "fem/model/Model.hpp"
#include "fem/model/Results.hpp"

namespace beamrotor {

/// Stations per element used by every writer: 4 intervals show the cubic deflection and the
/// linear moment of an end-loaded element and keep the tables small.
inline constexpr int kIntervalsPerElement = 4;

/// Distance along the line (m) of every node: line elements are walked in model order, each
/// starting where its start node lies (the first at 0) and adding its length; an element whose
/// start node was not reached yet continues from the furthest distance so far. For a chain of
/// elements from the first node this is the arc length from that node. nullopt for nodes on
/// no line element (springs to ground, lumped masses off the line).
std::vector<std::optional<double>> lineCoordinates(const Model& model);

/// One sampling place on a line element.
struct LinePlace {
  int element = -1;  ///< index into model.elements()
  double s = 0;      ///< fraction of the element's length, 0 at its start node
  double x = 0;      ///< distance along the line (m), see lineCoordinates
};

/// intervalsPerElement + 1 places on every line element (ends included), in the element order
/// and station order of recoverBeamFields. Joints appear twice (end of one element, start of
/// the next) so that jumps, e.g. of stress at a diameter step, show as vertical steps.
std::vector<LinePlace> placesAlongLine(const Model& model, int intervalsPerElement);

/// Displacements (global frame, ux uy uz (m), rx ry rz (rad)) at fraction s of a line element.
/// Exact nodal values at the ends; between them, axial displacement and twist are linear and
/// the two transverse deflections are cubic Hermite in the element's local frame, with the
/// bending rotations their slopes. This is exact for Euler-Bernoulli elements without span
/// loads and an interpolation of exact nodal values otherwise (Timoshenko elements, span
/// loads). It assumes the element's end rotations are its nodes' rotations (no end releases).
std::array<double, kDofKinds> displacementAt(const LineElement& element, const NodalField& field,
                                             double s);

/// One static sample: place, displacements, section forces (element frame) and stress.
struct StaticStation {
  LinePlace place;
  std::array<double, kDofKinds> displacement{};  ///< global frame, ux ... rz
  SectionForces forces;                          ///< element frame, see SectionForces
  double stress = 0;                             ///< largest |normal stress| (Pa)
  double shear = 0;                              ///< largest transverse shear stress (Pa)
};

/// Samples a static solution at placesAlongLine(model, intervalsPerElement).
std::vector<StaticStation> sampleStatics(const Model& model, const NodalField& displacement,
                                         int intervalsPerElement = kIntervalsPerElement);

/// The station of the largest stress (the first one on ties); nullopt without line elements.
std::optional<StaticStation> largestStress(const std::vector<StaticStation>& stations);

/// The station of the largest shear stress (the first one on ties); nullopt without line
/// elements.
std::optional<StaticStation> largestShear(const std::vector<StaticStation>& stations);

}  // namespace beamrotor

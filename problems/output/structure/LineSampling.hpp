// Samples a solved nodal field along the line elements (beams, shafts): where each station
// lies along the line and, for statics, what the recovery (fem/assembly/Recovery.hpp) finds
// there: displacements by each element's own interpolation (hinges included), section forces
// and stress. The CSV tables and the charts read these samples; the largest values are the
// exact element peaks (fem/assembly/ElementExtrema.hpp), placed along the line here.
#pragma once

#include <array>
#include <optional>
#include <span>
#include <vector>

#include "fem/assembly/ElementExtrema.hpp"
#include "fem/assembly/Recovery.hpp"
#include "fem/model/LineElement.hpp"
#include "fem/model/Model.hpp"
#include "fem/model/Results.hpp"
#include "fem/model/SignedStress.hpp"

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

/// One static sample: place, displacements, section forces (element frame) and stress.
struct StaticStation {
  LinePlace place;
  std::array<double, kDofKinds> displacement{};  ///< global frame, see displacementAlong
  SectionForces forces;                          ///< element frame, see SectionForces
  double stress = 0;                             ///< largest |normal stress| (Pa)
  double shear = 0;                              ///< largest transverse shear stress (Pa)
  YFibreStresses fibres;  ///< signed normal stress at the top and bottom fibre (Pa)
  double shearY = 0;      ///< shear stress of Vy alone, signed as Vy (Pa)
  double shearZ = 0;      ///< shear stress of Vz alone, signed as Vz (Pa)
};

/// Samples a static solution at placesAlongLine(model, intervalsPerElement).
std::vector<StaticStation> sampleStatics(const LoadedSolution& solution,
                                         int intervalsPerElement = kIntervalsPerElement);

/// The stations of each element in a sampling, found in one pass (sampleStatics keeps each
/// element's stations together), so that reading a member's stations costs their own number,
/// not the model's.
class StationsByElement {
 public:
  StationsByElement(const std::vector<StaticStation>& stations, std::size_t elementCount);
  /// The stations of element `element` in station order; empty for one not sampled.
  std::span<const StaticStation> of(int element) const;

 private:
  const std::vector<StaticStation>* stations_;
  std::vector<std::pair<std::size_t, std::size_t>> range_;  ///< per element: first, count
};

/// A largest value over the line elements and its place along the line.
struct LinePeak {
  LinePlace place;
  double value = 0;
};

/// The largest of one kind of the element peaks of a static solution (elementPeaks: exact,
/// not sampled), with its place; nullopt without line elements, NaN when any element's value
/// is not finite (largestPeak).
std::optional<LinePeak> largestAlongLine(const Model& model, const std::vector<ElementPeaks>& peaks,
                                         BeamPeak ElementPeaks::*kind);

}  // namespace beamrotor

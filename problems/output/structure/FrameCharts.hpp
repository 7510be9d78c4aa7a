// The whole-frame charts of a static analysis: the deformed shape over the undeformed frame
// (displacements magnified, the factor stated), and the bending moment diagram drawn across
// the members on their tension side, the largest |M| written at their exact places. Planar
// frames are drawn in their plane at true proportions, 3d frames in a 3d view.
//
// The chart carries its data in the script (gnuplot datablocks), and its cost is bounded
// whatever the frame's size: the outline and the deformed shape draw at most kOutlinePoints
// places (every station, else the element ends, else the member ends), the moment diagrams
// the kDiagramMembers members of the largest moments (fewer when their stations pass
// kDiagramPoints), and the labels the kMomentLabels largest moments and the named joints when
// there are at most kJointLabels.
#pragma once

#include <array>
#include <cstddef>
#include <string>
#include <vector>

#include "fem/assembly/MemberEnvelope.hpp"
#include "fem/assembly/MemberExtrema.hpp"
#include "fem/model/Model.hpp"
#include "fem/model/Results.hpp"
#include "problems/output/files/Gnuplot.hpp"
#include "problems/output/structure/LineSampling.hpp"

namespace beamrotor {

inline constexpr std::size_t kOutlinePoints = 40000;
inline constexpr std::size_t kDiagramPoints = 20000;
inline constexpr std::size_t kDiagramMembers = 50;
inline constexpr std::size_t kMomentLabels = 12;
inline constexpr std::size_t kJointLabels = 40;

/// One static solution of a frame as the chart draws it: its stations (sampleStatics, by
/// element), each member's resultant ranges (memberForceRanges, in Model::members() order),
/// its largest displacement (largestDisplacement) and its nodal displacements (which move
/// the rigid ties' ends; null draws them unmoved).
struct FrameDrawing {
  const Model* model = nullptr;
  const StationsByElement* stations = nullptr;
  const std::vector<std::array<ComponentRange, 6>>* ranges = nullptr;
  double largestDisplacement = 0;
  const NodalField* displacement = nullptr;
};

/// The rigid ties (links, end offsets, diaphragms; Model::rigidTies) are drawn on every frame
/// chart as thin dashed lines from master to follower, moved with the solution or shape; at
/// most kTieLines of them (the first), the title saying so.
inline constexpr std::size_t kTieLines = 2000;

/// Every frame chart draws its axes in metres and labels moments in kN m and displacements in
/// mm, or in the user's `units` where set (OutputUnits.hpp).
///
/// Two panels: the deformed shape and the moment diagram (Mz in a planar frame; Mz and My in
/// a 3d one, each along the local axis that shows its tension side).
ChartScript frameChart(const std::string& caption, const std::string& chartName,
                       const FrameDrawing& frame, bool planar, const OutputUnits& units = {});

/// The envelope of the bending moments over the load combinations drawn on the frame: one
/// panel per moment (Mz in a planar frame; Mz and My in a 3d one), on each member the largest
/// and smallest value along it (memberEnvelope, one list per member in Model::members() order)
/// drawn as the moment diagram is, the band between them hatched; the frame's largest and
/// smallest value labelled with the combination that governs it (`names`, by the stations'
/// maxBy and minBy). The same bounds as frameChart: the outline within kOutlinePoints, the
/// bands of the kDiagramMembers members of the largest moments.
ChartScript frameEnvelopeChart(const std::string& caption, const std::string& chartName,
                               const Model& model,
                               const std::vector<std::vector<EnvelopeStation>>& envelope,
                               const std::vector<std::string>& names, bool planar,
                               const OutputUnits& units = {});

/// Mode or buckling shapes of a frame (each scaled to a largest nodal translation of 1,
/// displayModeShape): one panel per shape, at most kShapePanels, the deformed frame (each
/// element sampled by its own interpolation, its translation drawn at kShapeShare of the
/// frame's size) over the outline, planar frames in their plane and 3d frames in the static
/// chart's 3d view; each panel titled by `titles[i]`. The named joints are labelled on the
/// first panel when there are at most kJointLabels. Bounded as frameChart: every panel draws at
/// most kOutlinePoints / panels places.
inline constexpr std::size_t kShapePanels = 6;
ChartScript frameShapesChart(const std::string& caption, const std::string& chartName,
                             const Model& model, const std::vector<Mode>& modes,
                             const std::vector<std::string>& titles, bool planar,
                             const OutputUnits& units = {});

}  // namespace beamrotor

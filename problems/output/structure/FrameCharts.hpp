// The whole-frame charts of a static analysis: the deformed shape over the undeformed frame
// (displacements magnified, the factor stated), and the bending moment diagram drawn across
// every member on its tension side, each member's largest |M| written at its exact place.
// Planar frames are drawn in their plane at true proportions, 3d frames in a 3d view.
#pragma once

#include <string>
#include <vector>

#include "fem/model/Model.hpp"
#include "fem/model/Results.hpp"
#include "problems/output/files/CsvTable.hpp"
#include "problems/output/files/Gnuplot.hpp"

namespace beamrotor {

/// One member on the chart: its memberTable and the CSV file it was written to.
struct MemberSeries {
  std::string name;
  const CsvTable* table = nullptr;
  std::string csvFile;
};

/// Two panels: the deformed shape and the moment diagram (Mz in a planar frame; Mz and My in
/// a 3d one, each along the local axis that shows its tension side).
ChartScript frameChart(const std::string& caption, const std::string& chartName,
                       const Model& model, const NodalField& displacement,
                       const std::vector<MemberSeries>& members, bool planar);

}  // namespace beamrotor

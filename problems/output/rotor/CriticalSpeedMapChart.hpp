// gnuplot script of the undamped critical-speed map: critical speeds against bearing stiffness
// on log axes, the pinned-bearing and free-free asymptotes as horizontal lines, and the
// speed-dependent bearings' kxx and kyy against speed over them.
#pragma once

#include <string>
#include <vector>

#include "fem/rotor/CriticalSpeedMap.hpp"
#include "problems/deck/OutputUnits.hpp"
#include "problems/output/files/CsvTable.hpp"
#include "problems/output/files/Gnuplot.hpp"

namespace beamrotor {

/// A table and the file it is written to.
struct MapChartData {
  const CsvTable& table;
  std::string file;
};

/// `map`: criticalSpeedMapTable's; `bearings`: mapBearingsTable's (no rows: nothing drawn),
/// naming `bearingNames` in order; `crossings`: mapCrossingsTable's, marked as points.
ChartScript criticalSpeedMapDiagram(const std::string& caption, const std::string& chartName,
                                    const CriticalSpeedMap& result, const MapChartData& map,
                                    const MapChartData& bearings, const MapChartData& crossings,
                                    const std::vector<std::string>& bearingNames,
                                    const OutputUnits& units = {});

}  // namespace beamrotor

// The CSV tables of a critical-speed-map analysis: the map itself and the speed-dependent
// bearings' direct stiffnesses drawn over it.
#pragma once

#include <string>
#include <vector>

#include "fem/rotor/CriticalSpeedMap.hpp"
#include "problems/output/files/CsvTable.hpp"
#include "problems/run/RotorRunResult.hpp"

namespace beamrotor {

/// Column name of the j-th (1-based) critical speed in criticalSpeedMapTable.
std::string mapColumn(int j);

/// One row per stiffness: stiffness (N/m), then critical_1, critical_2, ... (rpm).
CsvTable criticalSpeedMapTable(const std::string& title, const CriticalSpeedMap& map);

/// One row per bearing and table speed: bearing (name), bearing_index (1, 2, ...), speed_rpm,
/// kxx and kyy (N/m, the bearing's axes as the deck writes them).
CsvTable mapBearingsTable(const std::string& title,
                          const std::vector<BearingStiffnessCurve>& bearings);

/// One row per crossing of a bearing's kxx or kyy with a line of the map: bearing (name),
/// direction (kxx or kyy), critical_speed (1, 2, ...), speed_rpm, stiffness (N/m).
CsvTable mapCrossingsTable(const std::string& title,
                           const std::vector<BearingStiffnessCurve>& bearings);

}  // namespace beamrotor

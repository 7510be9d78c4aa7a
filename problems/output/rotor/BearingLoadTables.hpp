// The CSV tables of a bearing-loads analysis: the load of each bearing and the shaft's sag.
#pragma once

#include <string>
#include <vector>

#include "fem/rotor/GravityLoads.hpp"
#include "problems/output/files/CsvTable.hpp"

namespace beamrotor {

/// One row per bearing: bearing (name), x (m), fy, fz (N, the force the bearing exerts on the
/// shaft: its support reaction) and load (N, its magnitude: what the bearing carries).
CsvTable bearingLoadsTable(const std::string& title, const GravityLoads& loads,
                           const std::vector<std::string>& names);

/// One row per node along the shaft: x (m), uy, uz (m).
CsvTable sagTable(const std::string& title, const GravityLoads& loads);

}  // namespace beamrotor

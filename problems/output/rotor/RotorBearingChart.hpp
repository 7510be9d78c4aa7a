// The chart of the plain journal bearings' operating points against speed: eccentricity
// ratio, the four stiffness and the four damping coefficients.
#pragma once

#include <string>
#include <vector>

#include "problems/deck/OutputUnits.hpp"
#include "problems/output/files/CsvTable.hpp"
#include "problems/output/files/Gnuplot.hpp"

namespace beamrotor {

/// Three panels against speed (rpm) from a journalBearingsTable in csvFile holding the
/// bearings named (in their bearing_index order): eccentricity ratio; kxx kxy kyx kyy (MN/m); cxx cxy cyx cyy (kN s/m). One colour
/// per coefficient, one dash pattern per bearing.
ChartScript journalBearingsDiagram(const std::string& caption, const std::string& chartName,
                                   const CsvTable& table, const std::string& csvFile,
                                   const std::vector<std::string>& bearingNames,
                                   const OutputUnits& units = {});

}  // namespace beamrotor

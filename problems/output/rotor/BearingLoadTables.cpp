// CSV tables of the bearing loads (see BearingLoadTables.hpp).
#include "problems/output/rotor/BearingLoadTables.hpp"

#include <cmath>

namespace beamrotor {

CsvTable bearingLoadsTable(const std::string& title, const GravityLoads& loads,
                           const std::vector<std::string>& names) {
  CsvTable table(title, {{"bearing", ""}, {"x", "m"}, {"fy", "N"}, {"fz", "N"}, {"load", "N"}});
  for (std::size_t i = 0; i < loads.bearings.size(); ++i) {
    const BearingForce& b = loads.bearings[i];
    table.addRow({names.at(i), b.x, b.fy, b.fz, std::hypot(b.fy, b.fz)});
  }
  return table;
}

CsvTable sagTable(const std::string& title, const GravityLoads& loads) {
  CsvTable table(title, {{"x", "m"}, {"uy", "m"}, {"uz", "m"}});
  for (std::size_t i = 0; i < loads.nodes.size(); ++i)
    table.addRow({loads.x[i], loads.uy[i], loads.uz[i]});
  return table;
}

}  // namespace beamrotor

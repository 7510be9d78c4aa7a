// CSV tables of the critical-speed map (see CriticalSpeedMapTables.hpp).
#include "problems/output/rotor/CriticalSpeedMapTables.hpp"

#include <utility>

#include "problems/output/rotor/RotorTables.hpp"

namespace beamrotor {

std::string mapColumn(int j) {
  return "critical_" + std::to_string(j);
}

CsvTable criticalSpeedMapTable(const std::string& title, const CriticalSpeedMap& map) {
  std::vector<CsvColumn> columns{{"stiffness", "N/m"}};
  const int count = map.speeds.empty() ? 0 : int(map.speeds.front().size());
  for (int j = 1; j <= count; ++j) columns.push_back({mapColumn(j), "rpm"});
  CsvTable table(title, columns);
  for (std::size_t i = 0; i < map.stiffness.size(); ++i) {
    std::vector<CsvCell> row{map.stiffness[i]};
    for (double s : map.speeds[i]) row.emplace_back(rpmOf(s));
    table.addRow(row);
  }
  return table;
}

CsvTable mapBearingsTable(const std::string& title,
                          const std::vector<BearingStiffnessCurve>& bearings) {
  CsvTable table(title, {{"bearing", ""},
                         {"bearing_index", ""},
                         {"speed_rpm", "rpm"},
                         {"kxx", "N/m"},
                         {"kyy", "N/m"}});
  for (std::size_t b = 0; b < bearings.size(); ++b)
    for (std::size_t s = 0; s < bearings[b].speeds.size(); ++s)
      table.addRow({bearings[b].name, (long long)(b + 1), rpmOf(bearings[b].speeds[s]),
                    bearings[b].kxx[s], bearings[b].kyy[s]});
  return table;
}

CsvTable mapCrossingsTable(const std::string& title,
                           const std::vector<BearingStiffnessCurve>& bearings) {
  CsvTable table(title, {{"bearing", ""},
                         {"direction", ""},
                         {"critical_speed", ""},
                         {"speed_rpm", "rpm"},
                         {"stiffness", "N/m"}});
  for (const BearingStiffnessCurve& b : bearings)
    for (const auto& [direction, crossings] :
         {std::pair{"kxx", &b.kxxCrossings}, std::pair{"kyy", &b.kyyCrossings}})
      for (const MapCrossing& c : *crossings)
        table.addRow({b.name, std::string(direction), (long long)(c.line + 1), rpmOf(c.speed),
                      c.stiffness});
  return table;
}

}  // namespace beamrotor

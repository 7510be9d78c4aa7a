// gnuplot script of the critical-speed map (see CriticalSpeedMapChart.hpp).
#include "problems/output/rotor/CriticalSpeedMapChart.hpp"

#include <sstream>

#include "problems/output/files/ChartParts.hpp"
#include "problems/output/rotor/CriticalSpeedMapTables.hpp"
#include "problems/output/rotor/RotorTables.hpp"

namespace beamrotor {

ChartScript criticalSpeedMapDiagram(const std::string& caption, const std::string& chartName,
                                    const CriticalSpeedMap& result, const MapChartData& mapData,
                                    const MapChartData& bearingData, const MapChartData& crossingData,
                                    const std::vector<std::string>& bearingNames,
                                    const OutputUnits& units) {
  // The speeds as the tables hold them: rpm, or the user's speed unit.
  const OutputUnits::Shown speedUnit = units.valueIn("rpm", {1, "rpm"});
  const OutputUnits::Shown stiffness = units.columnIn("N/m", {1, "N/m"});
  const auto shownRpm = [&](double radPerSecond) { return rpmOf(radPerSecond) * speedUnit.factor; };
  const CsvTable& map = mapData.table;
  const CsvTable& bearings = bearingData.table;
  const std::string& mapFile = mapData.file;
  const std::string& bearingsFile = bearingData.file;
  const int count = int(map.columns().size()) - 1;
  // Axes: the map's stiffness range; speeds of the map and both asymptotes (the bearings'
  // curves are clipped to them).
  PositiveRange k, rpm;
  for (double v : map.numbers("stiffness")) k.include(v);
  for (int j = 1; j <= count; ++j)
    for (double v : map.numbers(mapColumn(j))) rpm.include(v);
  for (double v : result.pinned) rpm.include(shownRpm(v));
  for (double v : result.freeFree) rpm.include(shownRpm(v));

  std::vector<std::string> titles{"rigid bearings", "free-free rotor"};
  for (int j = 1; j <= count; ++j) titles.push_back("critical speed " + std::to_string(j));
  for (const std::string& b : bearingNames)
    for (const char* d : {" kxx", " kyy"}) titles.push_back("bearing " + b + d);
  titles.push_back("critical speeds on the bearings");
  const int width = 820 + keyWidth(titles), height = 680;

  std::ostringstream body;
  body << "  set encoding utf8\n  set title " << captionText(caption) << " font ',13'\n"
       << "  set grid xtics ytics mxtics mytics linecolor rgb 'gray80', linecolor rgb 'gray92'\n"
       << "  set key outside right top\n" << logAxis("x", k) << logAxis("y", rpm)
       << "  set xlabel "
       << gnuplotText("bearing stiffness k [" + stiffness.unit + "] (isotropic, at every bearing)")
       << "\n  set ylabel " << gnuplotText("undamped critical speed [" + speedUnit.unit + "]")
       << "\n  plot ";
  const auto asymptote = [&](const std::vector<double>& speeds, const std::string& title,
                             const char* style) {
    for (std::size_t j = 0; j < speeds.size(); ++j)
      body << number(shownRpm(speeds[j])) << " with lines " << style << " "
           << (j == 0 ? "title " + gnuplotText(title) : std::string("notitle")) << ", \\\n       ";
  };
  asymptote(result.pinned, "rigid bearings", "dashtype 2 linewidth 1.5 linecolor rgb 'gray30'");
  asymptote(result.freeFree, "free-free rotor", "dashtype 3 linewidth 1.5 linecolor rgb 'gray50'");
  for (int j = 1; j <= count; ++j)
    body << (j > 1 ? ", \\\n       " : "") << gnuplotFile(mapFile) << " skip 1 using 1:"
         << map.column(mapColumn(j)) << " with linespoints linewidth 2 pointtype 7 pointsize 0.5 "
         << colour(j - 1) << " title " << gnuplotText("critical speed " + std::to_string(j));
  // Bearings: stiffness across, speed up, so a crossing with a map line is a critical speed.
  // Each bearing its own dark colour, kxx solid and kyy dashed and half as wide, drawn over it;
  // even bearings wide, odd ones narrower on top: equal bearings, and a bearing whose kyy equals
  // its kxx, stay visible one within the other. Five bearings, two directions: ten styles.
  static const char* const kBearingColours[] = {"black", "#8c564b", "#555555", "#6b6b00",
                                                "#004c4c"};
  const int index = bearings.column("bearing_index"), speed = bearings.column("speed_rpm");
  for (std::size_t b = 0; b < bearingNames.size(); ++b)
    for (const char* d : {"kxx", "kyy"})
      body << ", \\\n       " << gnuplotFile(bearingsFile) << " skip 1 using ($" << index
           << " == " << b + 1 << " ? $" << bearings.column(d) << " : NaN):" << speed
           << " with lines linewidth "
           << (d[1] == 'x' ? (b % 2 ? "3" : "5") : (b % 2 ? "1.5" : "2.5"))
           << " dashtype " << (d[1] == 'x' ? 1 : 2) << " linecolor rgb '" << kBearingColours[b % 5]
           << "' title "
           << gnuplotText("bearing " + bearingNames[b] + " " + d);
  if (crossingData.table.rowCount() > 0)
    body << ", \\\n       " << gnuplotFile(crossingData.file) << " skip 1 using "
         << crossingData.table.column("stiffness") << ":" << crossingData.table.column("speed_rpm")
         << " with points pointtype 7 pointsize 1.3 linecolor rgb 'black' title "
            "'critical speeds on the bearings'";
  body << "\n";
  return {chartName, "Undamped critical-speed map: critical speeds against bearing stiffness",
          width, height, body.str()};
}

}  // namespace beamrotor

// Files of the rotor analyses (see RotorOutput.hpp).
#include "problems/output/rotor/RotorOutput.hpp"

#include "problems/output/files/TableUnits.hpp"

#include <algorithm>
#include <numbers>
#include <optional>
#include <string>
#include <vector>

#include "problems/deck/parse/Field.hpp"
#include "problems/output/rotor/BearingLoadTables.hpp"
#include "problems/output/rotor/CriticalSpeedMapChart.hpp"
#include "problems/output/rotor/CriticalSpeedMapTables.hpp"
#include "problems/output/rotor/LevelOneOutput.hpp"
#include "problems/output/files/ChartParts.hpp"
#include "problems/output/files/FileNames.hpp"
#include "problems/output/files/TableUnits.hpp"
#include "problems/output/rotor/RotorBearingChart.hpp"
#include "problems/output/rotor/RotorCharts.hpp"
#include "problems/output/rotor/RotorFileNames.hpp"
#include "problems/output/rotor/RotorOrbitChart.hpp"
#include "problems/output/rotor/RotorStabilityChart.hpp"
#include "problems/output/rotor/RotorTables.hpp"
#include "problems/output/rotor/RotorVtk.hpp"
#include "problems/output/rotor/RunUpOutput.hpp"
#include "problems/output/structure/VtkWriter.hpp"

namespace beamrotor {

namespace {

/// The excitation orders a Campbell analysis draws: its critical speeds' order, then the rest.
std::vector<double> campbellOrders(const CampbellOutcome& r) {
  std::vector<double> orders{r.order};
  orders.insert(orders.end(), r.furtherOrders.begin(), r.furtherOrders.end());
  return orders;
}

/// The caption, without its parameter list when that would not fit above one chart.
std::string fitted(const std::string& caption) {
  constexpr std::size_t kWidest = 90;  // characters across a 900-pixel chart title
  const std::size_t list = caption.find(" (");
  return caption.size() > kWidest && list != std::string::npos ? caption.substr(0, list) : caption;
}

/// x as formatNumber writes it, the exponent without '+' and leading zeros: 1e6, 2.5e-5.
std::string stiffnessText(double x) {
  std::string s = formatNumber(x);
  const std::size_t e = s.find('e');
  if (e == std::string::npos) return s;
  std::string exponent = s.substr(e + 1), sign;
  if (exponent[0] == '+' || exponent[0] == '-') {
    sign = exponent[0] == '-' ? "-" : "";
    exponent.erase(0, 1);
  }
  exponent.erase(0, std::min(exponent.find_first_not_of('0'), exponent.size() - 1));
  return s.substr(0, e + 1) + sign + exponent;
}

}  // namespace

PreparedRotor prepareRotor(const RotorModesResult& r, const std::string& stem) {
  PreparedRotor p;
  p.modes = rotorModesTable(modesCsv(stem), r);
  return p;
}

PreparedRotor prepareRotor(const CampbellOutcome& r, const std::string& stem) {
  PreparedRotor p;
  p.campbell = campbellTable(campbellCsv(stem), r.campbell);
  std::vector<CriticalSpeed> all = r.criticalSpeeds;
  all.insert(all.end(), r.furtherCriticalSpeeds.begin(), r.furtherCriticalSpeeds.end());
  p.critical = criticalSpeedsTable(criticalSpeedsCsv(stem), all);
  if (!r.journals.empty()) p.bearings = journalBearingsTable(journalBearingsCsv(stem), r.journals);
  return p;
}

PreparedRotor prepareRotor(const UnbalanceOutcome& r, const std::string& stem) {
  PreparedRotor p;
  p.unbalance = unbalanceTable(unbalanceCsv(stem), r.unbalance, r.responsePoints);
  if (r.operating) p.api684 = api684Table(api684Csv(stem), r);
  return p;
}

PreparedRotor prepareRotor(const RigidBodyOutcome&, const std::string&) {
  return {};  // all of it is in results.json
}

PreparedRotor prepareRotor(const FrequencyResponseOutcome& r, const std::string& stem) {
  PreparedRotor p;
  p.frf = frequencyResponseTable(frequencyResponseCsv(stem), r.response);
  return p;
}

PreparedRotor prepareRotor(const CriticalSpeedMapOutcome& r, const std::string& stem) {
  PreparedRotor p;
  p.map = criticalSpeedMapTable(criticalSpeedMapCsv(stem), r.map);
  p.mapBearings = mapBearingsTable(mapBearingsCsv(stem), r.bearings);
  p.mapCrossings = mapCrossingsTable(mapCrossingsCsv(stem), r.bearings);
  return p;
}

PreparedRotor prepareRotor(const BearingLoadsOutcome& r, const std::string& stem) {
  PreparedRotor p;
  p.bearingLoads = bearingLoadsTable(bearingLoadsCsv(stem), r.loads, r.bearingNames);
  p.sag = sagTable(sagCsv(stem), r.loads);
  return p;
}

PreparedRotor prepareRotor(const LevelOneOutcome& r, const std::string& stem) {
  PreparedRotor p;
  p.levelOne = levelOneTable(levelOneCsv(stem), r.screening);
  return p;
}

PreparedRotor prepareRotor(const RunUpOutcome& r, const std::string& stem) {
  PreparedRotor p;
  p.runUp = runUpTable(runUpCsv(stem), r);
  p.runUpHistory = runUpHistoryTable(runUpHistoryCsv(stem), r);
  return p;
}

void writeRotorFiles(const RotorFiles& f, const RotorModesResult& r) {
  const std::string& stem = f.stem;
  f.tables.modes->write(f.dir / modesCsv(stem));
  std::vector<PvdEntry> entries;
  for (std::size_t m = 0; m < r.modes.size(); ++m) {
    const int number = int(m) + 1;
    writeRotorModeVtu(f.dir / modeVtu(stem, number), f.model, r.modes[m], number);
    writeOrbitVtu(f.dir / orbitVtu(stem, number), f.model, r.modes[m]);
    entries.push_back({double(number), modeVtu(stem, number)});
  }
  writePvd(f.dir / collectionPvd(stem), entries);
  const CsvTable orbits =
      f.tables.orbits ? *f.tables.orbits
                      : inUnits(modeOrbitsTable(orbitsCsv(stem), r, f.model), f.units);
  orbits.write(f.dir / orbitsCsv(stem));
  if (f.charts && !r.modes.empty())
    drawChart(f.dir, modeOrbitsChart(fitted(f.caption), orbitsChart(stem), r, f.model, orbits,
                                     orbitsCsv(stem), f.units));
}

void writeRotorFiles(const RotorFiles& f, const CampbellOutcome& r) {
  const std::string& stem = f.stem;
  const PreparedRotor& p = f.tables;
  p.campbell->write(f.dir / campbellCsv(stem));
  p.critical->write(f.dir / criticalSpeedsCsv(stem));
  if (p.bearings) p.bearings->write(f.dir / journalBearingsCsv(stem));
  if (!f.charts) return;
  const std::string caption = fitted(f.caption);
  // The operating range, with the margins its critical speeds require.
  std::optional<OperatingBand> band;
  if (r.operating) band = bandOfCriticalSpeeds(*r.operating, r.criticalSpeeds);
  if (p.campbell->rowCount() > 0) {
    drawChart(f.dir,
              campbellDiagram(caption, campbellChart(stem), *p.campbell, campbellCsv(stem),
                              *p.critical, criticalSpeedsCsv(stem), campbellOrders(r), band,
                              f.units));
    drawChart(f.dir,
              stabilityDiagram(caption, stabilityChart(stem), *p.campbell, campbellCsv(stem),
                               r.onset ? std::optional<double>(r.onset->rpm) : std::nullopt, band,
                               f.units));
  }
  if (p.bearings && p.bearings->rowCount() > 0) {
    std::vector<std::string> names;
    for (const JournalBearingCurve& j : r.journals) names.push_back(j.name);
    drawChart(f.dir, journalBearingsDiagram(caption, journalBearingsChart(stem), *p.bearings,
                                            journalBearingsCsv(stem), names, f.units));
  }
}

void writeRotorFiles(const RotorFiles& f, const UnbalanceOutcome& r) {
  const std::string& stem = f.stem;
  const PreparedRotor& p = f.tables;
  p.unbalance->write(f.dir / unbalanceCsv(stem));
  if (p.api684) p.api684->write(f.dir / api684Csv(stem));
  // The operating range, with the margins its response peaks require.
  std::optional<OperatingBand> band;
  if (r.operating) band = bandOfPeaks(*r.operating, r.peaks);
  if (f.charts && p.unbalance->rowCount() > 0)
    drawChart(f.dir, unbalanceResponseChart(
                         fitted(f.caption), unbalanceChart(stem), *p.unbalance,
                         unbalanceCsv(stem), r.responsePoints, band,
                         r.stability && r.stability->onset
                             ? std::optional<double>(r.stability->onset->rpm)
                             : std::nullopt,
                         f.units));
}

void writeRotorFiles(const RotorFiles&, const RigidBodyOutcome&) {}  // results.json holds it

void writeRotorFiles(const RotorFiles& f, const FrequencyResponseOutcome& r) {
  const std::string& stem = f.stem;
  f.tables.frf->write(f.dir / frequencyResponseCsv(stem));
  if (f.charts && f.tables.frf->rowCount() > 0)
    drawChart(f.dir, frequencyResponseDiagram(fitted(f.caption), frequencyResponseChart(stem),
                                              *f.tables.frf, frequencyResponseCsv(stem),
                                              r.output + " / " + r.input, f.units));
}

void writeRotorFiles(const RotorFiles& f, const CriticalSpeedMapOutcome& r) {
  const std::string& stem = f.stem;
  const PreparedRotor& p = f.tables;
  p.map->write(f.dir / criticalSpeedMapCsv(stem));
  std::vector<std::string> names;
  for (const BearingStiffnessCurve& b : r.bearings) names.push_back(b.name);
  if (!names.empty()) {
    p.mapBearings->write(f.dir / mapBearingsCsv(stem));
    p.mapCrossings->write(f.dir / mapCrossingsCsv(stem));
  }
  const OutputUnits::Shown k = f.units.valueIn("N/m", {1, "N/m"});
  const std::string what =
      "undamped, gyroscopics neglected: k = " + stiffnessText(r.map.stiffness.front() * k.factor) +
      " to " + stiffnessText(r.map.stiffness.back() * k.factor) + " " + k.unit +
      " at all bearings, " +
      std::to_string(r.map.stiffness.size()) + " points";
  if (f.charts && p.map->rowCount() > 0)
    drawChart(f.dir,
              criticalSpeedMapDiagram(fitted(f.caption) + "\n" + what, criticalSpeedMapChart(stem),
                                      r.map, {*p.map, criticalSpeedMapCsv(stem)},
                                      {*p.mapBearings, mapBearingsCsv(stem)},
                                      {*p.mapCrossings, mapCrossingsCsv(stem)}, names, f.units));
}

void writeRotorFiles(const RotorFiles& f, const BearingLoadsOutcome&) {
  f.tables.bearingLoads->write(f.dir / bearingLoadsCsv(f.stem));
  f.tables.sag->write(f.dir / sagCsv(f.stem));
}

void writeRotorFiles(const RotorFiles& f, const LevelOneOutcome& r) {
  f.tables.levelOne->write(f.dir / levelOneCsv(f.stem));
  const LevelOneResult& s = r.screening;
  const OutputUnits::Shown speed = f.units.of("rpm");
  const std::string what = "at " + labelNumber(s.speed * 30 / std::numbers::pi * speed.factor) +
                           " " + speed.unit + ", cross-coupling at " + r.station + ": " +
                           levelOneVerdict(s);
  if (f.charts && f.tables.levelOne->rowCount() > 0)
    drawChart(f.dir, levelOneDiagram(fitted(f.caption) + "\n" + what, levelOneChart(f.stem), s,
                                     levelOneCsv(f.stem), f.units));
  if (f.charts)
    drawChart(f.dir, criticalSpeedRatioDiagram(fitted(f.caption) + "\n" + what,
                                               criticalSpeedRatioChart(f.stem), s.map));
}

void writeRotorFiles(const RotorFiles& f, const RunUpOutcome& r) {
  const std::string& stem = f.stem;
  f.tables.runUp->write(f.dir / runUpCsv(stem));
  f.tables.runUpHistory->write(f.dir / runUpHistoryCsv(stem));
  if (!f.charts || r.responsePoints.empty()) return;
  if (f.tables.runUp->rowCount() > 0)
    drawChart(f.dir, runUpAmplitudeChart(fitted(f.caption), runUpChart(stem), *f.tables.runUp,
                                         runUpCsv(stem), r, f.units));
  if (f.tables.runUpHistory->rowCount() > 1)
    drawChart(f.dir, runUpOrbitsChart(fitted(f.caption), runUpOrbitChart(stem),
                                      *f.tables.runUpHistory, runUpHistoryCsv(stem), r, f.units));
  if (f.tables.runUpHistory->rowCount() > 1 && !r.runUp.journals.empty())
    drawChart(f.dir, runUpJournalsChart(fitted(f.caption), runUpJournalChart(stem),
                                        *f.tables.runUpHistory, runUpHistoryCsv(stem), r, f.units));
}

}  // namespace beamrotor

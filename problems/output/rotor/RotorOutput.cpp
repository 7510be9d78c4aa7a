// Files of the rotor analyses (see RotorOutput.hpp).
#include "problems/output/rotor/RotorOutput.hpp"

#include <algorithm>
#include <optional>
#include <string>
#include <vector>

#include "problems/deck/parse/Field.hpp"
#include "problems/output/rotor/BearingLoadTables.hpp"
#include "problems/output/rotor/CriticalSpeedMapChart.hpp"
#include "problems/output/rotor/CriticalSpeedMapTables.hpp"
#include "problems/output/files/FileNames.hpp"
#include "problems/output/rotor/RotorBearingChart.hpp"
#include "problems/output/rotor/RotorCharts.hpp"
#include "problems/output/rotor/RotorFileNames.hpp"
#include "problems/output/rotor/RotorOrbitChart.hpp"
#include "problems/output/rotor/RotorStabilityChart.hpp"
#include "problems/output/rotor/RotorTables.hpp"
#include "problems/output/rotor/RotorVtk.hpp"
#include "problems/output/structure/VtkWriter.hpp"

namespace beamrotor {

namespace {

/// The excitation orders a Campbell analysis draws: its critical speeds' order, then the rest.
std::vector<double> campbellOrders(const RotorOutcome& r) {
  std::vector<double> orders{r.order};
  orders.insert(orders.end(), r.furtherOrders.begin(), r.furtherOrders.end());
  return orders;
}

}  // namespace

PreparedRotor prepareRotor(const AnalysisOutcome& a, const std::string& stem) {
  const RotorOutcome& r = *resultOf<RotorOutcome>(a);
  PreparedRotor p;
  if (r.modes) p.modes = rotorModesTable(modesCsv(stem), *r.modes);
  if (r.campbell) {
    p.campbell = campbellTable(campbellCsv(stem), *r.campbell);
    std::vector<CriticalSpeed> all = r.criticalSpeeds;
    all.insert(all.end(), r.furtherCriticalSpeeds.begin(), r.furtherCriticalSpeeds.end());
    p.critical = criticalSpeedsTable(criticalSpeedsCsv(stem), all);
    if (!r.journals.empty())
      p.bearings = journalBearingsTable(journalBearingsCsv(stem), r.journals);
  }
  if (r.unbalance) p.unbalance = unbalanceTable(unbalanceCsv(stem), *r.unbalance, r.responsePoints);
  if (r.unbalance && r.operating) p.api684 = api684Table(api684Csv(stem), r);
  if (r.frequencyResponse)
    p.frf = frequencyResponseTable(frequencyResponseCsv(stem), *r.frequencyResponse);
  if (r.map) {
    p.map = criticalSpeedMapTable(criticalSpeedMapCsv(stem), *r.map);
    p.mapBearings = mapBearingsTable(mapBearingsCsv(stem), r.mapBearings);
    p.mapCrossings = mapCrossingsTable(mapCrossingsCsv(stem), r.mapBearings);
  }
  if (r.gravityLoads) {
    p.bearingLoads = bearingLoadsTable(bearingLoadsCsv(stem), *r.gravityLoads, r.bearingNames);
    p.sag = sagTable(sagCsv(stem), *r.gravityLoads);
  }
  return p;
}

namespace {

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

void writeRotorFiles(const PreparedRotor& p, const AnalysisOutcome& a, const std::string& stem,
                     const Model& model, const std::filesystem::path& dir,
                     const std::string& fullCaption, bool charts) {
  const RotorOutcome& r = *resultOf<RotorOutcome>(a);
  const std::string caption = fitted(fullCaption);
  // The operating range on the charts against speed, with the margins its critical speeds
  // (Campbell) or its response peaks (unbalance) require.
  std::optional<OperatingBand> band;
  if (r.operating)
    band = r.unbalance ? bandOfPeaks(*r.operating, r.peaks)
                       : bandOfCriticalSpeeds(*r.operating, r.criticalSpeeds);
  if (p.modes) {
    p.modes->write(dir / modesCsv(stem));
    std::vector<PvdEntry> entries;
    for (std::size_t m = 0; m < r.modes->modes.size(); ++m) {
      const int number = int(m) + 1;
      writeRotorModeVtu(dir / modeVtu(stem, number), model, r.modes->modes[m], number);
      writeOrbitVtu(dir / orbitVtu(stem, number), model, r.modes->modes[m]);
      entries.push_back({double(number), modeVtu(stem, number)});
    }
    writePvd(dir / collectionPvd(stem), entries);
    const CsvTable orbits = modeOrbitsTable(orbitsCsv(stem), *r.modes, model);
    orbits.write(dir / orbitsCsv(stem));
    if (charts && !r.modes->modes.empty())
      drawChart(dir, modeOrbitsChart(caption, orbitsChart(stem), *r.modes, model, orbits,
                                     orbitsCsv(stem)));
  }
  if (p.campbell) {
    p.campbell->write(dir / campbellCsv(stem));
    p.critical->write(dir / criticalSpeedsCsv(stem));
    if (charts && p.campbell->rowCount() > 0)
      drawChart(dir, campbellDiagram(caption, campbellChart(stem), *p.campbell, campbellCsv(stem),
                                     *p.critical, criticalSpeedsCsv(stem), campbellOrders(r),
                                     band));
    if (charts && p.campbell->rowCount() > 0)
      drawChart(dir, stabilityDiagram(
                         caption, stabilityChart(stem), *p.campbell, campbellCsv(stem),
                         r.onset ? std::optional<double>(r.onset->rpm) : std::nullopt, band));
  }
  if (p.frf) {
    p.frf->write(dir / frequencyResponseCsv(stem));
    if (charts && p.frf->rowCount() > 0)
      drawChart(dir, frequencyResponseDiagram(caption, frequencyResponseChart(stem), *p.frf,
                                              frequencyResponseCsv(stem),
                                              r.frfOutput + " / " + r.frfInput));
  }
  if (p.bearings) {
    p.bearings->write(dir / journalBearingsCsv(stem));
    std::vector<std::string> names;
    for (const JournalBearingCurve& j : r.journals) names.push_back(j.name);
    if (charts && p.bearings->rowCount() > 0)
      drawChart(dir, journalBearingsDiagram(caption, journalBearingsChart(stem), *p.bearings,
                                            journalBearingsCsv(stem), names));
  }
  if (p.map) {
    p.map->write(dir / criticalSpeedMapCsv(stem));
    std::vector<std::string> names;
    for (const BearingStiffnessCurve& b : r.mapBearings) names.push_back(b.name);
    if (!names.empty()) {
      p.mapBearings->write(dir / mapBearingsCsv(stem));
      p.mapCrossings->write(dir / mapCrossingsCsv(stem));
    }
    const std::string what = "undamped, gyroscopics neglected: k = " +
                             stiffnessText(r.map->stiffness.front()) + " to " +
                             stiffnessText(r.map->stiffness.back()) + " N/m at all bearings, " +
                             std::to_string(r.map->stiffness.size()) + " points";
    if (charts && p.map->rowCount() > 0)
      drawChart(dir, criticalSpeedMapDiagram(caption + "\n" + what, criticalSpeedMapChart(stem),
                                             *r.map, {*p.map, criticalSpeedMapCsv(stem)},
                                             {*p.mapBearings, mapBearingsCsv(stem)},
                                             {*p.mapCrossings, mapCrossingsCsv(stem)}, names));
  }
  if (p.bearingLoads) {
    p.bearingLoads->write(dir / bearingLoadsCsv(stem));
    p.sag->write(dir / sagCsv(stem));
  }
  if (p.unbalance) {
    p.unbalance->write(dir / unbalanceCsv(stem));
    if (p.api684) p.api684->write(dir / api684Csv(stem));
    if (charts && p.unbalance->rowCount() > 0)
      drawChart(dir, unbalanceResponseChart(caption, unbalanceChart(stem), *p.unbalance,
                                            unbalanceCsv(stem), r.responsePoints, band));
  }
}

}  // namespace beamrotor

// The files of a run-up analysis: the amplitude of each response point per revolution against
// speed, the time histories (speed, angle, uy and uz of each point, the energy account), and
// their charts: amplitude against speed through the criticals, and the orbits.
#pragma once

#include <string>

#include "problems/deck/OutputUnits.hpp"
#include "problems/output/files/CsvTable.hpp"
#include "problems/output/files/Gnuplot.hpp"
#include "problems/run/RotorRunResult.hpp"

namespace beamrotor {

inline std::string runUpCsv(const std::string& stem) {
  return stem + "_runup.csv";
}
inline std::string runUpHistoryCsv(const std::string& stem) {
  return stem + "_runup_history.csv";
}
inline std::string runUpChart(const std::string& stem) {
  return stem + "_runup";
}
inline std::string runUpOrbitChart(const std::string& stem) {
  return stem + "_runup_orbits";
}
inline std::string runUpJournalChart(const std::string& stem) {
  return stem + "_runup_journals";
}

/// One row per revolution: time (s, its end), speed (rad/s, its mean), speed_rpm, then per
/// point <p>_amplitude (largest distance from the revolution's mean position), <p>_uy_half_range
/// and <p>_uz_half_range (m). The points complete the same revolutions.
CsvTable runUpTable(const std::string& title, const RunUpOutcome& r);

/// One row per sample: time (s), speed (rad/s), speed_rpm, angle (rad), <p>_uy, <p>_uz (m) per
/// point, <b>_y, <b>_z (m, the journal centre from the bearing's centre) and <b>_eccentricity per
/// nonlinear journal and film_torque (N m, their drag on the spin), per rub station <r>_radial
/// (m), <r>_normal_force, <r>_friction_force (N) and <r>_rub_torque (N m), then the energy
/// account (J, RunUpEnergy): kinetic, strain, dissipated, gyroscopic, film, rub, work,
/// energy_balance.
CsvTable runUpHistoryTable(const std::string& title, const RunUpOutcome& r);

/// Amplitude against speed from a runUpTable in csvFile, one curve per point, its peak named
/// in the key.
ChartScript runUpAmplitudeChart(const std::string& caption, const std::string& chartName,
                                const CsvTable& table, const std::string& csvFile,
                                const RunUpOutcome& r, const OutputUnits& units = {});

/// The orbits uz against uy of every point over the run, from a runUpHistoryTable in csvFile,
/// axes to equal scale.
ChartScript runUpOrbitsChart(const std::string& caption, const std::string& chartName,
                             const CsvTable& history, const std::string& csvFile,
                             const RunUpOutcome& r, const OutputUnits& units = {});

/// The nonlinear journals' centres in their bearings over the run (y / c, z / c), inside the
/// clearance circle, from a runUpHistoryTable in csvFile (its positions in `units`). Every
/// second journal is dashed: the journals of a symmetric rotor run on one path.
ChartScript runUpJournalsChart(const std::string& caption, const std::string& chartName,
                               const CsvTable& history, const std::string& csvFile,
                               const RunUpOutcome& r, const OutputUnits& units = {});

}  // namespace beamrotor

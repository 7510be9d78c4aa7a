// The names of the files a rotor analysis writes (see FileNames.hpp for the others).
#pragma once

#include <string>

#include "problems/output/files/FileNames.hpp"

namespace beamrotor {

/// Campbell: one row per speed, the tracked lines' frequencies, damping and whirl.
inline std::string campbellCsv(const std::string& stem) {
  return stem + "_campbell.csv";
}
/// Campbell: one row per critical speed.
inline std::string criticalSpeedsCsv(const std::string& stem) {
  return stem + "_critical_speeds.csv";
}
/// Unbalance: one row per speed, amplitude and phase at every response point.
inline std::string unbalanceCsv(const std::string& stem) {
  return stem + "_unbalance.csv";
}
/// Campbell: one row per plain journal bearing and table speed.
inline std::string journalBearingsCsv(const std::string& stem) {
  return stem + "_bearings.csv";
}
/// Unbalance with an operating range: one row per response point and peak (API 684).
inline std::string api684Csv(const std::string& stem) {
  return stem + "_api684.csv";
}
/// Frequency response: one row per excitation frequency.
inline std::string frequencyResponseCsv(const std::string& stem) {
  return stem + "_frf.csv";
}
/// Rotor modes: every node's orbit sampled, per mode (the orbit chart's data).
inline std::string orbitsCsv(const std::string& stem) {
  return stem + "_orbits.csv";
}
/// Charts (without extension).
/// Rotor modes: orbit ellipses along the shaft, a panel per mode.
inline std::string orbitsChart(const std::string& stem) {
  return stem + "_orbits";
}
/// Critical-speed map: one row per bearing stiffness.
inline std::string criticalSpeedMapCsv(const std::string& stem) {
  return stem + "_map.csv";
}
/// Critical-speed map: the speed-dependent bearings' kxx and kyy, one row per table speed.
inline std::string mapBearingsCsv(const std::string& stem) {
  return stem + "_map_bearings.csv";
}
/// Bearing loads: one row per bearing.
inline std::string bearingLoadsCsv(const std::string& stem) {
  return stem + "_bearing_loads.csv";
}
/// Bearing loads: the shaft's sag, one row per node.
inline std::string sagCsv(const std::string& stem) {
  return stem + "_sag.csv";
}
/// Critical-speed map: where the bearings' kxx and kyy meet its lines, one row each.
inline std::string mapCrossingsCsv(const std::string& stem) {
  return stem + "_map_crossings.csv";
}
inline std::string criticalSpeedMapChart(const std::string& stem) {
  return stem + "_map";
}
inline std::string frequencyResponseChart(const std::string& stem) {
  return stem + "_frf";
}
inline std::string journalBearingsChart(const std::string& stem) {
  return stem + "_bearings";
}
inline std::string campbellChart(const std::string& stem) {
  return stem + "_campbell";
}
/// Campbell: the whirl frequencies coloured by log decrement, and the decrements.
inline std::string stabilityChart(const std::string& stem) {
  return stem + "_stability";
}
inline std::string unbalanceChart(const std::string& stem) {
  return stem + "_unbalance";
}
/// Rotor modes: the orbits of mode `number` as polylines.
inline std::string orbitVtu(const std::string& stem, int number) {
  return modeVtu(stem + "_orbits", number);
}

}  // namespace beamrotor

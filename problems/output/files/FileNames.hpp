// The names of the files in a results directory, in one place: the writers create them and
// results.json lists them, so scripts find a file by reading its name rather than guessing.
#pragma once

#include <string>
#include <vector>

#include "problems/run/RunResult.hpp"

namespace beamrotor {

/// An analysis name made safe as a file stem: letters, digits, '-', '_' and '.' are kept,
/// anything else becomes '_' (a deck may call an analysis "eta = 0.4 / left").
std::string fileStem(const std::string& analysisName);

/// Throws std::invalid_argument when two analyses of a run would write the same files.
void requireDistinctFileStems(const std::vector<AnalysisOutcome>& analyses);

inline constexpr const char* kResultsJson = "results.json";
inline constexpr const char* kSweepJson = "sweep.json";
/// `beamrotor converge`'s summary (problems/converge/ConvergeOutput.hpp).
inline constexpr const char* kConvergenceJson = "convergence.json";
inline constexpr const char* kSweepCsv = "sweep.csv";

/// Statics: fields along the line, one row per station.
inline std::string fieldsCsv(const std::string& stem) {
  return stem + "_fields.csv";
}
/// Statics of a model with springs or bearings: the force each exerts on the structure.
inline std::string springsCsv(const std::string& stem) {
  return stem + "_springs.csv";
}
/// Statics with supports: one row per reaction component.
inline std::string reactionsCsv(const std::string& stem) {
  return stem + "_reactions.csv";
}
/// Statics with load cases: one row per case or combination and reported value.
inline std::string casesCsv(const std::string& stem) {
  return stem + "_cases.csv";
}
/// Modal: one row per mode.
inline std::string modesCsv(const std::string& stem) {
  return stem + "_modes.csv";
}
/// Buckling: one row per load factor.
inline std::string bucklingFactorsCsv(const std::string& stem) {
  return stem + "_factors.csv";
}
/// Modal and buckling: display-scaled mode shapes along the line (the charts' data).
inline std::string shapesCsv(const std::string& stem) {
  return stem + "_shapes.csv";
}
/// Statics: the mesh with its displacements and section forces.
inline std::string staticVtu(const std::string& stem) {
  return stem + ".vtu";
}
/// Modal: mode `number` (1-based).
std::string modeVtu(const std::string& stem, int number);
/// Statics with load cases: case or combination `number` (1-based, cases first, then
/// combinations, in deck order).
std::string caseVtu(const std::string& stem, int number);
/// Statics with load cases: the ParaView collection of every case and combination, stepped
/// through by their number.
inline std::string casesPvd(const std::string& stem) {
  return stem + "_cases.pvd";
}
/// A ParaView collection: the modes of an analysis, or one analysis over a sweep.
inline std::string collectionPvd(const std::string& stem) {
  return stem + ".pvd";
}
/// Charts of an analysis (without extension: .gp script, .svg and .png images).
inline std::string diagramsChart(const std::string& stem) {
  return stem + "_diagrams";
}
/// Statics of a frame: deformed shape and moment diagram of the whole frame.
inline std::string frameShapeChart(const std::string& stem) {
  return stem + "_frame";
}
/// The same under load case or combination `number` (numbered as caseVtu): `<stem>_frame_case_NN`.
std::string caseFrameChart(const std::string& stem, int number);
/// Statics of a frame with combinations: the envelope of the bending moments on the frame.
inline std::string frameEnvelopeChart(const std::string& stem) {
  return stem + "_frame_envelope";
}
inline std::string shapesChart(const std::string& stem) {
  return stem + "_shapes";
}
inline std::string sweepChart(const std::string& stem) {
  return "sweep_" + stem;
}
/// Transient: the named histories, one row per sample time.
inline std::string historyCsv(const std::string& stem) {
  return stem + "_history.csv";
}
/// Transient: the histories' chart (without extension).
inline std::string historyChart(const std::string& stem) {
  return stem + "_history";
}
/// Transient: stored frame `number` (1-based) of the displacement field.
std::string frameVtu(const std::string& stem, int number);
/// Sub-directory of a sweep for value number `index` of `count`: value_000, value_001, ...
std::string sweepValueDirectory(std::size_t index, std::size_t count);
/// A short sweep without per-value directories: value `index`'s fields along the line, which
/// its overlaid diagrams read: static_fields_value_000.csv, ...
std::string sweepFieldsCsv(const std::string& stem, std::size_t index, std::size_t count);

}  // namespace beamrotor

// A solved run made ready for writing, in memory: checked for NaN and infinity, sampled along
// the line, its results.json document and every CSV table built, except what grows with the
// load cases and combinations: their results.json entries and the load cases' table are made
// a case at a time as they are written. The results directory is written from it, and the
// Python module hands the same document and tables, made whole (wholeResults), to Python, so
// the two never disagree.
#pragma once

#include <filesystem>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "fem/assembly/MemberEnvelope.hpp"
#include "problems/deck/OutputUnits.hpp"
#include "problems/deck/OutputChoices.hpp"
#include "problems/output/files/CsvTable.hpp"
#include "problems/output/JsonWriter.hpp"
#include "problems/output/ResultsDocument.hpp"
#include "problems/output/structure/CaseEnvelope.hpp"
#include "problems/output/structure/LineSampling.hpp"
#include "problems/output/structure/StaticExtremes.hpp"
#include "problems/output/rotor/RotorOutput.hpp"
#include "problems/run/RunResult.hpp"

namespace beamrotor {

/// A load case or combination of a static analysis, sampled for its VTK file.
struct PreparedCase {
  const CaseOutcome* outcome = nullptr;
  int index = -1;                       ///< into the analysis' cases (casesOf)
  std::string vtu;                      ///< <stem>_case_NN.vtu, NN = index + 1
  std::vector<StaticStation> stations;
  const StaticExtremes* extremes = nullptr;  ///< its extremes (PreparedRun::extremes)
  std::vector<ElementPeaks> peaks;  ///< every line element's (elementPeaks), for its VTK file
  /// Its extremes again with the member ranges' places, where runExtremes kept their values
  /// alone or none (RangesKept): its charts draw them.
  std::optional<StaticExtremes> placed;

  /// Its extremes with the member ranges' places.
  const StaticExtremes& withPlaces() const { return placed ? *placed : *extremes; }
};

/// What one analysis writes, computed before writing.
struct PreparedAnalysis {
  const AnalysisOutcome* outcome = nullptr;
  std::string stem;                     ///< file stem of its files
  std::vector<StaticStation> stations;  ///< statics only
  /// Statics: the extremes of its own solution and of each case (PreparedRun::extremes).
  const AnalysisExtremes* extremes = nullptr;
  std::optional<CsvTable> fields;       ///< statics: <stem>_fields.csv
  std::optional<CsvTable> springs;      ///< statics with springs or bearings: <stem>_springs.csv
  std::optional<CsvTable> reactions;    ///< statics with supports: <stem>_reactions.csv
  std::optional<CsvTable> modes;   ///< modal: <stem>_modes.csv; buckling: <stem>_factors.csv
  std::optional<CsvTable> shapes;  ///< modal, buckling: <stem>_shapes.csv
  std::optional<CsvTable> history;      ///< transient: <stem>_history.csv
  std::optional<CsvTable> baseMotion;   ///< base motion: <stem>_base_motion.csv
  std::optional<PreparedRotor> rotor;   ///< rotor analyses
  /// Statics of a frame: <stem>_member_<name>.csv each, or the one <stem>_members.csv
  /// (oneMembersTable).
  std::vector<CsvTable> members;
  /// Frame with combinations: <stem>_envelope_<name>.csv each, or the one
  /// <stem>_envelopes.csv (oneMembersTable); the envelope along each member they hold.
  std::vector<CsvTable> envelopes;
  std::vector<std::vector<EnvelopeStation>> envelopeStations;
  /// Statics with combinations: the envelope over them (caseEnvelope).
  std::optional<CaseEnvelope> envelope;
  /// Statics with load cases: the VTK samples of the cases written (writtenCases), in order.
  std::vector<PreparedCase> cases;
  /// Statics with load cases: <stem>_cases.csv, held only once wholeResults made it (the
  /// results directory writes it a case at a time).
  std::optional<CsvTable> caseTable;
  std::vector<CsvTable> crank;          ///< crank-slider: motion, harmonics, lambda table
  std::vector<CsvTable> torsion;  ///< a train: interference, crossings, torques, response
  std::vector<CsvTable> moving;   ///< a moving load: influence lines, envelopes
  std::vector<CsvTable> spectrum;  ///< response spectrum: modes, displacements, reactions, members

  /// Every table this analysis has, each with its CSV file name, in writing order.
  std::vector<std::pair<std::string, const CsvTable*>> tables() const;
  /// The prepared case of index `index` into the analysis' cases; nullptr when not written.
  const PreparedCase* caseAt(int index) const;
};

struct PreparedRun {
  const RunResult* run = nullptr;  ///< must outlive this
  std::vector<AnalysisExtremes> extremes;  ///< per analysis, computed once (runExtremes)
  std::vector<PreparedAnalysis> analyses;
  ResultsDocument results;  ///< results.json, the cases' entries made as written (checked then)
  OutputUnits units;  ///< the units the tables are in (and the charts show)
};

/// Prepares run: a long line's fields table thinned (thinnedStations) unless
/// `choices.fullTables`; with combinations only the governing ones sampled for their VTK files
/// unless `choices.allCases` (writtenCases); every table in `choices.units` (inUnits; the
/// document stays SI). results.json's `cases[i].vtu` names the files written. Throws
/// std::runtime_error naming the first non-finite number outside the cases' entries (theirs
/// are refused as they are made), or analyses whose files would overwrite each other's.
PreparedRun prepareRun(const RunResult& run, const OutputChoices& choices = {});

/// The whole results.json document of prepared, checked as prepareRun checks it, and every
/// load cases' table held (PreparedAnalysis::caseTable), in prepared's units: what the Python
/// module hands over.
Json wholeResults(PreparedRun& prepared);

/// Writes results.json and every load cases' table (<stem>_cases.csv) into `dir`, a case at a
/// time: each case's entry is made, checked, written to both and dropped.
void writeResultsAndCaseTables(const PreparedRun& prepared, const std::filesystem::path& dir);

/// Only the results.json document of run, checked as prepareRun checks it, without its tables
/// (a long sweep's values, whose tables are not written).
Json prepareRunDocument(const RunResult& run);

}  // namespace beamrotor

// results.json of a run whose load cases' and combinations' entries are made one at a time as
// they are written (or asked for): a large frame's 200 combinations never hold theirs all at
// once. Made and written by JsonWriter.cpp (runDocument), with the layout of JsonWriter.hpp.
#pragma once

#include <array>
#include <cstddef>
#include <filesystem>
#include <functional>
#include <memory>
#include <string>
#include <vector>

#include "fem/model/DofMap.hpp"
#include "problems/output/JsonWriter.hpp"
#include "problems/output/structure/StaticExtremes.hpp"
#include "problems/run/RunResult.hpp"

namespace beamrotor {

/// The results.json entries of one static analysis' load cases and combinations, made one at
/// a time: a large frame's 200 combinations never hold all of theirs at once.
class CaseEntries {
 public:
  /// Those of `a` (extremes: its own, runExtremes), the analysis at position `analysis`.
  CaseEntries(const Model& model, std::shared_ptr<const DofMap> dofs,
              const std::array<bool, kDofKinds>& carried, const AnalysisOutcome& a,
              const AnalysisExtremes& extremes, std::size_t analysis);

  /// Position of the analysis in results.json's analyses.
  std::size_t analysis() const { return analysis_; }
  std::size_t size() const { return cases_->size(); }
  /// The entry of case i (its factors, reactions, point displacements, largest stresses, ...,
  /// warnings, and the "vtu" named by nameVtu).
  Json entry(std::size_t i) const;
  /// Names the VTK file written for case i (its entry's "vtu").
  void nameVtu(std::size_t i, std::string file) { vtus_.at(i) = std::move(file); }

 private:
  const Model* model_;
  std::shared_ptr<const DofMap> dofs_;
  std::array<bool, kDofKinds> carried_;
  const std::vector<CaseOutcome>* cases_;
  const std::vector<StaticExtremes>* extremes_;
  std::string stem_;
  bool memberDetail_;
  std::size_t analysis_;
  std::vector<std::string> vtus_;  ///< per case; empty: none written
};

/// results.json of one run whose load cases' entries are made only as they are written or
/// asked for: in `doc` each static analysis with cases holds them as an empty array, and
/// `cases` makes them. The run and its extremes must outlive it.
struct ResultsDocument {
  Json doc;
  std::vector<CaseEntries> cases;  ///< in the order of the analyses

  /// The whole document, every case's entry in its place (nothing checked).
  Json complete() const&;
  Json complete() &&;
  /// Writes results.json, the same bytes as writeJson(complete(), file), making each case's
  /// entry, refusing a NaN or infinity in it as requireFiniteNumbers does (its path from the
  /// document's root), writing it and dropping it, one at a time; `doc` itself is not checked
  /// here. `each(cases, entry)`, when given, sees every entry once it is written.
  void write(const std::filesystem::path& file,
             const std::function<void(const CaseEntries&, const Json&)>& each = {}) const;
};

/// results.json of one run, its cases' entries left to be made (ResultsDocument).
/// `extremes[i]` are those of run.analyses[i] (staticExtremes of its own solution and of each
/// load case and combination; empty for other kinds): the largest stresses, member extremes and
/// largest displacements are read from them.
ResultsDocument runDocument(const RunResult& run, const std::vector<AnalysisExtremes>& extremes);

}  // namespace beamrotor

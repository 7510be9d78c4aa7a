// Continuing a design study that stopped before its end: `beamrotor study DECK ... --resume
// DIR`, DIR being the partial results an interrupted study wrote (summary.json "partial") or
// the temporary directory (DIR.tmp-XXXXXX) of a study killed outright, whose rows were written
// as they finished. Every study writes resume.json when it starts (removed once it is
// complete): what makes its table this table. The continued study must be the same: the deck's
// text, the --set overrides and --formulation (which change every value), the number of points
// and the columns (their names and units; the output units chosen are no part of the table);
// and each stored row's parameter values must be those of its point here
// (other --sweep, --sample, --seed or sampling give other values). It then solves only the
// points missing, and its table is, byte for byte, the table of an uninterrupted run.
#pragma once

#include <filesystem>
#include <fstream>
#include <memory>
#include <string>

#include "problems/output/JsonWriter.hpp"
#include "problems/output/files/AtomicDirectory.hpp"
#include "problems/study/DesignPoints.hpp"
#include "problems/study/PointRanges.hpp"
#include "problems/study/StudyPoint.hpp"

namespace beamrotor {

/// The file that makes a results directory resumable.
inline constexpr const char* kResumeFile = "resume.json";

/// resume.json for the study of `plan` with `points` points.
Json studyIdentity(const StudyPlan& plan, long long points);

class StudyResumption {
 public:
  /// Opens DIR and checks it against the study (reading every stored row once); throws
  /// DeckError at "--resume DIR" saying what does not fit.
  StudyResumption(const std::filesystem::path& dir, const StudyPlan& plan,
                  const DesignPoints& points);
  /// The directory the continued study replaces by default: DIR itself, or for the temporary
  /// directory of a killed run the results directory it was being written for.
  std::filesystem::path destination() const;
  /// The points whose rows are stored, and how many.
  const PointRanges& done() const { return done_; }
  /// The stored rows in point order, one per call: the line as stored (newline included)
  /// and the row; false after the last.
  bool nextRow(std::string& line, StudyRow& row);
  /// A stored point's results directory (points/<k>/), if DIR has it.
  std::filesystem::path pointFiles(long long index) const;
  /// Once the continued study is in place: the temporary directory of a killed run is
  /// removed (its rows are now in the new results). Returns a sentence for the console, or
  /// "" when nothing was removed.
  std::string finish();

 private:
  std::filesystem::path dir_;
  std::unique_ptr<UnfinishedDirectory> unfinished_;  ///< held while reading a killed run's
  StudyRow shape_;
  PointRanges done_;
  std::ifstream table_;  ///< study.csv, past its header
};

}  // namespace beamrotor

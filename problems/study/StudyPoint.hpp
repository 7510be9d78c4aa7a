// One point of a design study: the deck re-read with the point's parameter values (so a
// parameter may move points, supports and loads and resize the mesh), solved with only the
// analyses its outputs and checks read, and reduced to one row. A point that fails records
// its error in the row's status; nothing else of it is kept.
#pragma once

#include <memory>
#include <string>
#include <vector>

#include "problems/deck/parse/DeckSource.hpp"
#include "problems/deck/study/DesignStudy.hpp"
#include "problems/deck/parse/Expression.hpp"
#include "problems/deck/parse/Units.hpp"
#include "problems/deck/study/Overrides.hpp"
#include "problems/run/DeckRunner.hpp"
#include "problems/run/RunResult.hpp"

namespace beamrotor {

/// What every point shares, read once.
struct StudyPlan {
  std::string deckPath;
  std::string deckText;                      ///< each solver parses its own YAML tree from it
  std::vector<ParameterOverride> overrides;  ///< --set
  std::string formulation;                   ///< --formulation, or empty
  DesignStudySpec spec;
  std::vector<std::string> parameterNames;  ///< the varied parameters, in spec order
  std::vector<std::string> checkNames;      ///< the deck's checks, deck order
  /// The unit each column holds its numbers in, told by the deck as it was read: a varied
  /// parameter's (parameterUnit: SI, or rpm for a bare one read by a *_rpm field), an
  /// output's and a check's computed value's (referenceUnit of the quantity).
  std::vector<FieldUnit> parameterUnits, outputUnits, checkUnits;
  std::vector<std::string> analyses;        ///< the analyses the outputs and checks read
  /// Whether points must take turns solving: ARPACK (modes, buckling, rotor modes, the
  /// central-difference step estimate) keeps its state in Fortran SAVE variables and is not
  /// safe to call from two threads at once. False when every analysis needed is static.
  bool exclusive = true;
  /// The lean path: each point's reading of the deck takes the expressions an earlier point
  /// met from their byte code (ExpressionMemo, one per solver) instead of parsing them again;
  /// false: every point reads the deck in full (the reference the lean path must equal).
  bool lean = true;
  /// The deck's `output:` choices: the worst point's directory is written with them (its
  /// charts and output units); study.csv and summary.json stay in the columns' units.
  DeckOutput output;
};

/// Where one point's time went (s, wall time of the thread that solved it). Not part of the
/// table: times differ from run to run, the table must not.
struct PointCost {
  double read = 0;      ///< reading the deck at the point's values
  double model = 0;     ///< building the model: mesh, elements, supports, loads
  double assembly = 0;  ///< static systems: numbering the dofs, assembling K and the loads
  double factor = 0;    ///< static systems: the factorisation (and the symbolic analysis)
  double solve = 0;     ///< the rest of the analyses: solves, error estimate, recovery
  double measure = 0;   ///< the deck's checks and the recorded outputs
  PointCost& operator+=(const PointCost& other);
};

/// One point's row.
struct StudyRow {
  long long index = 0;
  std::vector<double> parameters;
  std::vector<double> outputs;      ///< NaN where the point gave none (status says why)
  std::vector<double> checks;       ///< computed values; NaN where the check does not apply
  std::vector<signed char> passed;  ///< 1 pass, 0 fail, -1 does not apply
  std::string status = "ok";        ///< "ok" or the point's error, one line
  PointCost cost;
  bool ok() const { return status == "ok"; }
};

/// A row of the plan's shape holding no values (NaN, checks not applying), status "ok".
StudyRow blankRow(const StudyPlan& plan);

/// The plan for `deckPath` read with `overrides` (as deck), and spec.
StudyPlan makeStudyPlan(const std::string& deckPath, const std::string& deckText,
                        const Deck& deck, std::vector<ParameterOverride> overrides,
                        const std::string& formulation, DesignStudySpec spec);

/// Solves points of one plan; one per thread (each has its own YAML tree and evaluators).
class PointSolver {
 public:
  explicit PointSolver(const StudyPlan& plan);
  /// The row of point `index` at `values` (in plan.parameterNames order). Never throws for a
  /// point's own failure (bad input at these values, an analysis that fails): the row says it.
  StudyRow solve(long long index, const std::vector<double>& values) const;
  /// The deck at `values` solved with all its analyses, for the point's own results directory.
  /// Throws as runDeck does.
  RunResult solveFully(const std::vector<double>& values) const;
  /// How this solver's readings evaluated their expressions so far: from byte code (the lean
  /// path) and in full.
  long long expressionsFromByteCode() const { return memo_.memoEvaluations(); }
  long long expressionsInFull() const { return memo_.fullEvaluations(); }
  /// Static systems factorised with the symbolic analysis of an earlier point's, and analysed.
  long long symbolicReuses() const { return cache_.statics.reuses(); }
  long long symbolicAnalyses() const { return cache_.statics.analyses(); }

 private:
  Deck deckAt(const std::vector<double>& values) const;
  const StudyPlan& plan_;
  DeckSource source_;
  mutable ExpressionMemo memo_;  ///< this solver's only: solvers run on threads of their own
  /// The lean path's: what one point's static systems leave for the next (same thread).
  mutable RunCache cache_;
};

}  // namespace beamrotor

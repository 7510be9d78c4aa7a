// What solving one deck produced: the contract between the deck runner (problems/deck,
// problems/cli) and the writers (problems/output). Plain values; writers read these and the
// model's nodes and line elements, never element internals.
#pragma once

#include <cmath>
#include <memory>
#include <optional>
#include <string>
#include <utility>
#include <variant>
#include <vector>

#include "fem/assembly/Recovery.hpp"
#include "fem/assembly/SolutionPolynomials.hpp"
#include "fem/model/Loading.hpp"
#include "fem/model/Model.hpp"
#include "fem/model/Results.hpp"
#include "fem/modal/BaseMotion.hpp"
#include "fem/modal/ResponseSpectrum.hpp"
#include "fem/stability/StabilityResults.hpp"
#include "problems/deck/Deck.hpp"
#include "problems/run/AdequateChoice.hpp"
#include "problems/run/CrankSliderOutcome.hpp"
#include "problems/run/MovingLoadOutcome.hpp"
#include "problems/run/RotorRunResult.hpp"
#include "problems/run/TorsionOutcome.hpp"
#include "problems/run/TransientOutcome.hpp"

namespace beamrotor {

/// A closed-form comparison declared by a deck.
struct Check {
  std::string name;
  double computed = 0;
  double reference = 0;
  double tolerance = 0;  ///< on the relative error
  std::string quantity;  ///< what was measured, in deck syntax, e.g. "reaction left rz"
  /// `paper:` the figure a source prints when the reference is not it (e.g. the paper's own
  /// arithmetic), with `reason:` saying why the two differ; empty when the reference is it.
  std::optional<double> paper{};  // initializers: a check without a paper figure stops at quantity
  std::string reason{};
  double relError() const {
    return reference != 0 ? std::abs(computed - reference) / std::abs(reference)
                          : std::abs(computed);
  }
  bool pass() const { return std::isfinite(computed) && relError() <= tolerance; }
};

/// A static analysis under one load case or combination, on the run's model: its loads there
/// (Loading.hpp: member forces need its span loads) and its solution. The cases are solved as
/// further right-hand sides of one factorisation; a combination is the factored sum of its
/// cases' solutions (linear statics superpose), its loading their loadings factored.
struct CaseOutcome {
  std::string name;
  bool combination = false;
  std::vector<std::pair<std::string, double>> factors;  ///< a combination's: case, factor
  std::shared_ptr<const Loading> loading;
  StaticResult statics;
  std::vector<std::string> warnings;  ///< not errors, e.g. displacements past the model's size
  /// Its polynomials along the line elements when the analysis has combinations: a load
  /// case's recovered once, a combination's the factored sum of its cases' (null otherwise).
  std::shared_ptr<const SolutionPolynomials> polynomials;
  /// The solution as recovery reads it, on `model` (the run's model).
  LoadedSolution on(const Model& model) const {
    return {model, statics.displacement, loading.get(), polynomials.get()};
  }
};

/// A linear static analysis: its solution, and each load case and combination solved apart.
struct StaticOutcome {
  StaticResult statics;
  std::vector<CaseOutcome> cases;  ///< the load cases, then the combinations
  /// Whether the deck's `loads:` loads the structure; false when only its load cases do (the
  /// solution above is then the unloaded one, which the summary and charts leave out).
  bool ownLoads = true;
};

/// What one analysis produced: one value type per kind of result. A static analysis with
/// `second_order: true` gives both of its states (SecondOrderResult), a modal one (prestressed
/// or not) its modes, each rotor analysis its kind's type (RotorResult, RotorRunResult.hpp),
/// a torsion analysis the modes of its own model and a moving load its influence lines.
using AnalysisResult =
    std::variant<StaticOutcome, SecondOrderResult, ModalResult, BucklingResult, TransientOutcome,
                 RotorModesResult, CampbellOutcome, UnbalanceOutcome, RigidBodyOutcome,
                 FrequencyResponseOutcome, CriticalSpeedMapOutcome, BearingLoadsOutcome,
                 CrankSliderOutcome, TorsionOutcome, LevelOneOutcome, MovingLoadOutcome,
                 RunUpOutcome, ResponseSpectrumResult, BaseMotionResult>;

/// One analysis of a deck, solved.
struct AnalysisOutcome {
  std::string type;  ///< the deck's type for it (AnalysisKinds.hpp), e.g. "campbell"
  std::string name;  ///< the deck's name for it (defaults to the type)
  AnalysisResult result;
  std::vector<std::string> warnings;  ///< not errors, e.g. an over-refined mesh
};

/// The result of analysis `a` when it is an R; null otherwise.
template <class R>
const R* resultOf(const AnalysisOutcome& a) {
  return std::get_if<R>(&a.result);
}
template <class R>
R* resultOf(AnalysisOutcome& a) {
  return std::get_if<R>(&a.result);
}

/// Whether analysis `a` is one of the rotor analyses (its result a RotorResult).
inline bool isRotorResult(const AnalysisOutcome& a) {
  return std::visit([]<class R>(const R&) { return RotorResult<R>; }, a.result);
}

/// The static solution of a static analysis (with `second_order: true`, the second-order
/// state); null for the other kinds.
inline const StaticResult* staticsOf(const AnalysisOutcome& a) {
  if (const auto* s = resultOf<StaticOutcome>(a)) return &s->statics;
  if (const auto* s = resultOf<SecondOrderResult>(a)) return &s->secondOrder;
  return nullptr;
}
inline StaticResult* staticsOf(AnalysisOutcome& a) {
  return const_cast<StaticResult*>(staticsOf(std::as_const(a)));
}

/// The modes of a modal, torsion or response-spectrum analysis with the model they are shaped
/// on (a torsion analysis has its own); null for the other kinds.
struct ModesOn {
  const ModalResult* modes = nullptr;
  const Model* model = nullptr;
};
inline ModesOn modesOf(const AnalysisOutcome& a, const Model& deckModel) {
  if (const auto* m = resultOf<ModalResult>(a)) return {m, &deckModel};
  if (const auto* t = resultOf<TorsionOutcome>(a)) return {&t->modes, t->model.get()};
  if (const auto* s = resultOf<ResponseSpectrumResult>(a)) return {&s->modal, &deckModel};
  return {};
}

/// The load cases and combinations of a linear static analysis; none for the other kinds.
inline const std::vector<CaseOutcome>& casesOf(const AnalysisOutcome& a) {
  static const std::vector<CaseOutcome> none;
  const auto* s = resultOf<StaticOutcome>(a);
  return s ? s->cases : none;
}

/// One solved instance of a deck (one set of parameter values).
struct RunResult {
  std::string deckPath;
  std::string deckName;                                    ///< file stem, e.g. "pump_rod"
  std::vector<std::pair<std::string, double>> parameters;  ///< values used, deck order
  std::vector<std::pair<std::string, double>> reported;    ///< the deck's `report:` values
  /// The parameters set on the command line (--set), which chart titles name.
  std::vector<std::string> setParameters;
  /// The SI unit of each parameter or derived value the deck wrote with a unit ("m", "N").
  std::vector<std::pair<std::string, std::string>> units;
  std::shared_ptr<const Model> model;
  std::string dimension;  ///< "planar" or "3d"
  std::vector<AnalysisOutcome> analyses;
  std::vector<Check> checks;
  std::vector<std::string> skippedChecks;  ///< names of checks whose `when:` is false here
  double seconds = 0;                      ///< wall time to build and solve
  /// Its parts: building the model, the analyses, the checks.
  double modelSeconds = 0, analysesSeconds = 0, checksSeconds = 0;
  std::optional<AdequateChoice> adequate;  ///< `accuracy:` decks: the model chosen
  std::vector<std::string> warnings;       ///< the deck's own (implausible materials)
  /// The sections taken from the catalogue, with their tables' properties (y-y strong).
  std::vector<DeckCatalogSection> catalogSections;
};

/// A deck solved over a list of values of one parameter.
struct SweepResult {
  std::string parameter;
  /// Its values' unit (bareUnitName of parameterUnit): SI ("N", "m"), a bare one's from the
  /// fields it flows into ("rpm" for a *_rpm field); empty when dimensionless or unknown.
  std::string unit;
  std::vector<double> values;
  std::vector<RunResult> runs;  ///< one per value
};

}  // namespace beamrotor

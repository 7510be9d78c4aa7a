#include "problems/converge/ConvergeStudy.hpp"

#include <algorithm>
#include <cmath>
#include <string>
#include <variant>

#include "fem/timing/Median.hpp"
#include "problems/converge/ConvergenceRates.hpp"
#include "problems/deck/DeckReader.hpp"
#include "problems/deck/FieldUnits.hpp"
#include "problems/deck/structure/SectionNeeds.hpp"
#include "problems/run/DeckRunner.hpp"
#include "problems/run/Measure.hpp"
#include "problems/run/Overloaded.hpp"

namespace beamrotor {

namespace {

/// A quantity that changes by less than this (relative) when the discretisation is refined
/// once does not depend on it: far above the round-off of the shipped models' solves
/// (~1e-13), far below any discretisation error worth a study.
constexpr double kDiscretisationChange = 1e-9;

const DeckPlace kQuantityOption{0, 0, "--quantity"};

/// The quantity, the analysis it reads and the check giving its closed form (if any).
struct Target {
  Quantity quantity;
  const DeckAnalysis* analysis = nullptr;
  const DeckCheck* check = nullptr;
  std::string choice;  ///< how it was chosen
};

/// Time-step studies for transient analyses, mesh studies for the others.
bool refinesTimeStep(const DeckAnalysis& a) {
  return a.as<TransientSpec>() != nullptr;
}

/// Which analyses a study can refine: every kind but the rigid-body properties (integrals of
/// the section, the same on any mesh) and the crank-slider mechanism (closed forms, no mesh).
bool studiable(const DeckAnalysis& a) {
  return !a.as<RigidBodySpec>() && !a.as<CrankSliderSpec>();
}

/// Refuses a deck none of whose analyses a study can refine (nothingToConverge).
void requireSomethingToRefine(const Deck& deck) {
  const std::optional<std::string> why = nothingToConverge(deck);
  if (!why) return;
  const DeckPlace place = deck.analyses.empty() ? kQuantityOption : deck.analyses.front().place;
  throw DeckError(deck.path, place, *why);
}

const DeckAnalysis* analysisNamed(const Deck& deck, const std::string& name) {
  for (const DeckAnalysis& a : deck.analyses)
    if (a.name == name) return &a;
  return nullptr;
}

/// The deck's own check quantities in order (applicable ones, of analyses a study refines),
/// then one natural quantity per analysis: the lowest frequency of a modal or rotor analysis,
/// the largest stress of a static one with beams, the first history's largest |value| of a
/// transient one.
std::vector<Target> candidates(const Deck& deck) {
  std::vector<Target> out;
  for (const DeckCheck& k : deck.checks) {
    const DeckAnalysis* a = analysisNamed(deck, k.analysis);
    if (k.applicable && a && studiable(*a)) out.push_back({k.quantity, a, &k, ""});
  }
  for (const DeckAnalysis& a : deck.analyses) {
    std::string text;
    if (a.as<ModalSpec>() || a.as<RotorSpec>()) text = "frequency 1";
    if (a.as<StaticSpec>() && !deck.segments.empty()) text = "stress max";
    const auto* transient = a.as<TransientSpec>();
    if (transient && !transient->run.histories.empty())
      text = "history " + transient->run.histories.front().name + " maxabs";
    if (!text.empty()) out.push_back({parseQuantity(text), &a, nullptr, ""});
  }
  return out;
}

/// The deck reduced to the given analyses, without checks, sweep or accuracy target.
Deck studyDeck(const Deck& deck, const std::vector<const DeckAnalysis*>& analyses) {
  Deck d = deck;
  d.analyses.clear();
  for (const DeckAnalysis* a : analyses) d.analyses.push_back(*a);
  d.checks.clear();
  d.sweep.reset();
  d.accuracy.reset();  // the study chooses the meshes itself
  return d;
}

/// The candidate's value in a run, or nullopt when the run cannot give it.
std::optional<double> valueIn(const RunResult& run, const Target& t) {
  for (const AnalysisOutcome& a : run.analyses)
    if (a.name == t.analysis->name) try {
        const double v = measure(t.quantity, a, run);
        if (std::isfinite(v)) return v;
      } catch (const std::exception&) {
      }
  return std::nullopt;
}

/// Relative change of each candidate of one kind of refinement between the deck's own
/// discretisation and the next level (nullopt: not measurable there).
void measureChanges(const Deck& deck, const std::vector<Target>& all, bool timeStep,
                    std::vector<std::optional<double>>& change) {
  std::vector<const DeckAnalysis*> analyses;
  for (const Target& t : all)
    if (refinesTimeStep(*t.analysis) == timeStep &&
        std::find(analyses.begin(), analyses.end(), t.analysis) == analyses.end())
      analyses.push_back(t.analysis);
  if (analyses.empty()) return;
  const Deck coarse = studyDeck(deck, analyses);
  Deck fine = coarse;
  timeStep ? refineTimeStep(fine, 1) : refineMesh(fine, 1);
  RunResult a, b;
  try {
    a = runDeck(coarse);
    b = runDeck(fine);
  } catch (const DeckError&) {
    return;  // e.g. an explicit step the finer mesh makes unstable: no candidate here
  } catch (const DeckSolveError&) {
    return;
  }
  for (std::size_t i = 0; i < all.size(); ++i) {
    if (refinesTimeStep(*all[i].analysis) != timeStep) continue;
    const auto u = valueIn(a, all[i]), v = valueIn(b, all[i]);
    if (u && v) change[i] = std::abs(*v - *u) / std::max(std::abs(*u), 1e-300);
  }
}

/// The first candidate that depends on the discretisation, or the first one at all.
Target defaultTarget(const Deck& deck) {
  const std::vector<Target> all = candidates(deck);
  if (all.empty())
    throw DeckError(deck.path, kQuantityOption,
                    "the deck has no static, modal, rotor or transient quantity to study; name "
                    "one");
  std::vector<std::optional<double>> change(all.size());
  measureChanges(deck, all, false, change);
  measureChanges(deck, all, true, change);
  const auto describe = [&](const Target& t) {
    return t.check ? "check '" + t.check->name + "'" : "analysis '" + t.analysis->name + "'";
  };
  for (std::size_t i = 0; i < all.size(); ++i)
    if (change[i] && *change[i] > kDiscretisationChange) {
      Target t = all[i];
      char text[96];
      std::snprintf(text, sizeof text, "%.2g", *change[i]);
      t.choice = "the first quantity of the deck that changes with the " +
                 std::string(refinesTimeStep(*t.analysis) ? "time step" : "mesh") + " (" +
                 describe(t) + "; " + text + " relative on the first refinement)";
      return t;
    }
  // Nothing changes: every candidate is exact on the deck's own discretisation.
  const auto first = std::find_if(change.begin(), change.end(), [](auto c) { return c; });
  Target t = all[first == change.end() ? 0 : first - change.begin()];
  t.choice =
      "no quantity of the deck changes with the discretisation beyond round-off (its "
      "elements are exact here); " +
      describe(t) + " shown, its errors are round-off";
  return t;
}

Target resolveTarget(const Deck& deck, const std::string& text) {
  if (text.empty()) return defaultTarget(deck);
  Target t;
  for (const DeckCheck& k : deck.checks)
    if (k.applicable && k.quantity.text == text) {
      t.check = &k;
      break;
    }
  try {
    t.quantity = t.check ? t.check->quantity : parseQuantity(text);
  } catch (const std::invalid_argument& e) {
    throw DeckError(deck.path, kQuantityOption, e.what());
  }
  t.analysis = t.check ? analysisNamed(deck, t.check->analysis) : nullptr;
  for (const DeckAnalysis& a : deck.analyses)
    if (!t.analysis && answers(a.kind, t.quantity)) t.analysis = &a;
  if (!t.analysis)
    throw DeckError(deck.path, kQuantityOption,
                    "no analysis of the deck gives '" + t.quantity.text + "'");
  if (!studiable(*t.analysis))
    throw DeckError(deck.path, kQuantityOption,
                    "'" + t.quantity.text + "' reads a " + t.analysis->type() +
                        " analysis, which is the same on every mesh");
  t.choice = "as asked (--quantity)";
  return t;
}

/// What one solve of the studied analysis cost.
struct SolveCost {
  SolveTimings time;
  SystemSize size;
};

SolveCost costOf(const AnalysisOutcome& a) {
  return std::visit(
      Overloaded{[](const StaticOutcome& r) -> SolveCost {
                   return {r.statics.time, r.statics.size};
                 },
                 [](const SecondOrderResult& r) -> SolveCost {
                   return {r.secondOrder.time, r.secondOrder.size};
                 },
                 [](const ModalResult& r) -> SolveCost {
                   return {r.time, r.size};
                 },
                 [](const ResponseSpectrumResult& r) -> SolveCost {
                   return {r.modal.time, r.modal.size};
                 },
                 [](const TorsionOutcome& r) -> SolveCost {
                   return {r.modes.time, r.modes.size};
                 },
                 [](const BucklingResult& r) -> SolveCost {
                   return {r.time, r.size};
                 },
                 [](const TransientOutcome& r) -> SolveCost {
                   return {r.result.time, r.result.size};
                 },
                 [](const RotorModesResult& r) -> SolveCost {
                   return {r.time, r.size};
                 },
                 [](const CampbellOutcome& r) -> SolveCost {
                   return {r.campbell.time, r.campbell.size};
                 },
                 [](const UnbalanceOutcome& r) -> SolveCost {
                   return {r.unbalance.time, r.unbalance.size};
                 },
                 [](const RunUpOutcome& r) -> SolveCost { return {r.runUp.time, r.runUp.size}; },
                 // Never studied (a rigid body is not studiable, the others answer no
                 // quantity): nothing of them is timed.
                 [](const RigidBodyOutcome&) -> SolveCost { return {}; },
                 [](const FrequencyResponseOutcome&) -> SolveCost { return {}; },
                 [](const CriticalSpeedMapOutcome&) -> SolveCost { return {}; },
                 [](const BearingLoadsOutcome&) -> SolveCost { return {}; },
                 [](const LevelOneOutcome&) -> SolveCost { return {}; },
                 [](const BaseMotionResult&) -> SolveCost { return {}; },
                 // A mechanism has no mesh to refine (studiable): nothing of it is timed.
                 [](const CrankSliderOutcome&) -> SolveCost { return {}; },
                 // Its solves are many right-hand sides of one factorisation, not timed apart.
                 [](const MovingLoadOutcome&) -> SolveCost { return {}; }},
      a.result);
}

/// Solves one level, repeating short runs; the quantity is taken from the first run.
ConvergeLevel solveLevel(const Deck& deck, const Quantity& q, int level, int repeats) {
  ConvergeLevel out;
  out.level = level;
  std::vector<double> assembly, factor, solve, total;
  for (int r = 0; r < repeats; ++r) {
    const RunResult run = runDeck(deck);
    const AnalysisOutcome& a = run.analyses.front();
    const SolveCost cost = costOf(a);
    if (r == 0) {
      try {
        out.value = measure(q, a, run);
      } catch (const std::logic_error& e) {  // e.g. a point the deck does not name
        throw DeckError(deck.path, kQuantityOption, e.what());
      }
      out.elements = cost.size.elements;
      out.dofs = cost.size.freeDofs;
      if (const auto* t = deck.analyses.front().as<TransientSpec>())
        out.steps = int(std::lround(t->run.end / t->run.dt));
    }
    assembly.push_back(cost.time.assembly);
    factor.push_back(cost.time.factor);
    solve.push_back(cost.time.solve);
    total.push_back(cost.time.total);
    if (cost.time.total >= kShortRunSeconds) break;
  }
  out.runs = int(total.size());
  out.assembly = median(assembly);
  out.factor = median(factor);
  out.solve = median(solve);
  out.total = median(total);
  return out;
}

/// Reference, errors and observed orders of a solved series.
void measureErrors(ConvergeSeries& s, const DeckCheck* check) {
  const std::size_t n = s.levels.size();
  if (n == 0) return;
  if (check) {
    s.reference = check->reference;
  } else if (n < 3) {  // failed too early to extrapolate: the finest value, no order
    s.reference = s.levels.back().value;
    s.extrapolated = true;
  } else {
    const Extrapolation e =
        richardson(s.levels[n - 3].value, s.levels[n - 2].value, s.levels[n - 1].value);
    s.reference = e.value;
    s.extrapolated = true;
    s.extrapolationOrder = e.order;
  }
  for (std::size_t k = 0; k < n; ++k) {
    ConvergeLevel& l = s.levels[k];
    const double diff = std::abs(l.value - s.reference);
    l.error = s.reference != 0 ? diff / std::abs(s.reference) : diff;
    if (k > 0) l.order = observedOrder(s.levels[k - 1].error, l.error);
  }
}

}  // namespace

std::optional<std::string> nothingToConverge(const Deck& deck) {
  if (std::any_of(deck.analyses.begin(), deck.analyses.end(), studiable)) return std::nullopt;
  std::string kinds;
  for (const DeckAnalysis& a : deck.analyses) {
    kinds += kinds.empty() ? "" : ", ";
    kinds += a.type() + " '" + a.name + "'";
  }
  std::string why = "nothing to converge: the deck has no mesh or time step to refine (its "
                    "analyses, ";
  why += kinds;
  why += ", are closed forms that are the same at any discretisation); `beamrotor solve` gives "
         "their figures";
  return why;
}

ConvergeStudy runConvergence(const Deck& deck, const ConvergeOptions& options) {
  // 1. What to measure and against what.
  requireSomethingToRefine(deck);
  const Target t = resolveTarget(deck, options.quantity);
  if (options.levels < (t.check ? 2 : 3) || options.levels > 16)
    throw DeckError(deck.path, DeckPlace{0, 0, "--levels"},
                    std::string("must be from ") + (t.check ? "2" : "3") +
                        " (3 to extrapolate without a closed form) to 16, got " +
                        std::to_string(options.levels));
  const bool timeStep = refinesTimeStep(*t.analysis);
  ConvergeStudy study;
  study.deckPath = deck.path;
  study.deckName = deck.stem;
  study.quantity = t.quantity.text;
  study.unit = referenceUnit(t.quantity);
  study.analysis = t.analysis->name;
  if (t.check) study.check = t.check->name;
  study.refinement = timeStep ? "time step" : "mesh";
  study.choice = t.choice;

  // 2. Every method on every level: the element formulations on finer meshes (the finest within
  //    what a deck may ask for), or the deck's own scheme and elements on shorter time steps.
  const Deck base = studyDeck(deck, {t.analysis});
  if (!timeStep) {
    Deck finest = base;
    refineMesh(finest, options.levels - 1);
    double elements = 0;
    for (const DeckSegment& s : finest.segments) elements += s.elementEstimate();
    if (elements > kMaxElements)
      throw DeckError(deck.path, DeckPlace{0, 0, "--levels"},
                      "the finest mesh would have " + std::to_string(std::llround(elements)) +
                          " elements, more than the " + std::to_string(kMaxElements) +
                          " a deck may have; use fewer levels");
  }
  const std::vector<ConvergeMethod> methods =
      timeStep ? std::vector<ConvergeMethod>{{"time-step", "the deck's scheme, dt halved per level",
                                              deck.beam.theory, deck.beam.mass}}
               : convergeMethods(!t.analysis->as<StaticSpec>());
  for (const ConvergeMethod& method : methods) {
    ConvergeSeries series;
    series.method = method;
    for (int level = 0; level < options.levels; ++level) {
      Deck d = base;
      if (timeStep) {
        refineTimeStep(d, level);
      } else {
        useMethod(method, d);
        refineMesh(d, level);
        try {  // a Timoshenko method needs every general section's kappa
          requireSectionValues(d);
        } catch (const DeckError& e) {
          series.failure = e.what();
          break;
        }
      }
      try {
        series.levels.push_back(solveLevel(d, t.quantity, level, std::max(1, options.repeats)));
      } catch (const DeckSolveError& e) {
        series.failure = "level " + std::to_string(level) + ": " + e.message();
        std::replace(series.failure.begin(), series.failure.end(), '\n', ' ');
        break;
      }
    }
    // 3. Errors and rates.
    measureErrors(series, t.check);
    study.series.push_back(std::move(series));
  }
  return study;
}

}  // namespace beamrotor

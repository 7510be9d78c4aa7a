#include "problems/study/StudyPoint.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <mutex>
#include <new>
#include <variant>

#include "fem/timing/Stopwatch.hpp"
#include "problems/deck/DeckReader.hpp"
#include "problems/deck/FieldUnits.hpp"
#include "problems/deck/parse/Field.hpp"
#include "problems/deck/structure/FormulationOption.hpp"
#include "problems/deck/study/SweepOption.hpp"
#include "problems/run/DeckRunner.hpp"
#include "problems/run/Measure.hpp"

namespace beamrotor {

namespace {

constexpr double kMissing = std::numeric_limits<double>::quiet_NaN();

/// Held while an exclusive point solves (see StudyPlan::exclusive).
std::mutex& arpackTurn() {
  static std::mutex turn;
  return turn;
}

void addOnce(std::vector<std::string>& names, const std::string& name) {
  if (std::find(names.begin(), names.end(), name) == names.end()) names.push_back(name);
}

/// A message on one line (a CSV cell): line breaks become spaces.
std::string rowStatusText(std::string text) {
  std::replace(text.begin(), text.end(), '\n', ' ');
  std::replace(text.begin(), text.end(), '\r', ' ');
  return text;
}

/// The static systems' share of a run's analyses: assembly and factorisation.
void addStaticCost(const StaticResult& r, PointCost& cost) {
  cost.assembly += r.time.assembly;
  cost.factor += r.time.factor;
}

}  // namespace

PointCost& PointCost::operator+=(const PointCost& other) {
  read += other.read;
  model += other.model;
  assembly += other.assembly;
  factor += other.factor;
  solve += other.solve;
  measure += other.measure;
  return *this;
}

StudyRow blankRow(const StudyPlan& plan) {
  StudyRow row;
  row.parameters.assign(plan.parameterNames.size(), kMissing);
  row.outputs.assign(plan.spec.outputs.size(), kMissing);
  row.checks.assign(plan.checkNames.size(), kMissing);
  row.passed.assign(plan.checkNames.size(), -1);
  return row;
}

StudyPlan makeStudyPlan(const std::string& deckPath, const std::string& deckText,
                        const Deck& deck, std::vector<ParameterOverride> overrides,
                        const std::string& formulation, DesignStudySpec spec) {
  StudyPlan plan;
  plan.deckPath = deckPath;
  plan.deckText = deckText;
  plan.overrides = std::move(overrides);
  plan.formulation = formulation;
  plan.output = deck.output;
  for (const StudyParameter& p : spec.parameters) {
    plan.parameterNames.push_back(p.name);
    plan.parameterUnits.push_back(parameterUnit(deck, p.name));
  }
  for (const StudyOutput& o : spec.outputs) {
    addOnce(plan.analyses, o.analysis);
    plan.outputUnits.push_back(referenceUnit(o.quantity));
  }
  for (const DeckCheck& k : deck.checks) {
    plan.checkNames.push_back(k.name);
    plan.checkUnits.push_back(referenceUnit(k.quantity));
    addOnce(plan.analyses, k.analysis);
  }
  plan.exclusive = std::any_of(deck.analyses.begin(), deck.analyses.end(),
                               [&](const DeckAnalysis& a) {
                                 return !a.as<StaticSpec>() &&
                                        std::find(plan.analyses.begin(), plan.analyses.end(),
                                                  a.name) != plan.analyses.end();
                               }) ||
                   deck.accuracy.has_value();
  plan.spec = std::move(spec);
  return plan;
}

PointSolver::PointSolver(const StudyPlan& plan)
    : plan_(plan), source_(parseDeckText(plan.deckText, plan.deckPath)) {}

Deck PointSolver::deckAt(const std::vector<double>& values) const {
  std::vector<ParameterOverride> overrides = plan_.overrides;
  for (std::size_t j = 0; j < values.size(); ++j)
    overrides.push_back({plan_.parameterNames[j], values[j],
                         plan_.parameterNames[j] + "=" + formatNumber(values[j])});
  Deck deck = plan_.lean ? readDeck(source_, overrides, memo_) : readDeck(source_, overrides);
  if (!plan_.formulation.empty()) applyFormulationOption(plan_.formulation, deck);
  deck.sweep.reset();
  return deck;
}

RunResult PointSolver::solveFully(const std::vector<double>& values) const {
  const Deck deck = deckAt(values);
  std::unique_lock<std::mutex> turn(arpackTurn(), std::defer_lock);
  if (plan_.exclusive) turn.lock();
  return runDeck(deck);
}

StudyRow PointSolver::solve(long long index, const std::vector<double>& values) const {
  StudyRow row = blankRow(plan_);
  row.index = index;
  row.parameters = values;
  Stopwatch clock;
  try {
    Deck deck = deckAt(values);
    // Only the analyses something here reads.
    std::erase_if(deck.analyses, [&](const DeckAnalysis& a) {
      return std::find(plan_.analyses.begin(), plan_.analyses.end(), a.name) ==
             plan_.analyses.end();
    });
    row.cost.read = clock.lap();
    std::unique_lock<std::mutex> turn(arpackTurn(), std::defer_lock);
    if (plan_.exclusive) turn.lock();
    const RunResult run = runDeck(deck, plan_.lean ? &cache_ : nullptr);
    if (turn.owns_lock()) turn.unlock();
    const double runSeconds = clock.lap();
    row.cost.model = run.modelSeconds;
    for (const AnalysisOutcome& a : run.analyses) {
      if (const StaticResult* s = staticsOf(a)) addStaticCost(*s, row.cost);
      for (const CaseOutcome& c : casesOf(a)) addStaticCost(c.statics, row.cost);
    }
    row.cost.measure = run.checksSeconds;
    // The rest of the run (an `accuracy:` deck's whole search among them).
    row.cost.solve = std::max(0.0, runSeconds - row.cost.model - row.cost.assembly -
                                       row.cost.factor - row.cost.measure);
    for (std::size_t k = 0; k < plan_.spec.outputs.size(); ++k) {
      const StudyOutput& o = plan_.spec.outputs[k];
      for (const AnalysisOutcome& a : run.analyses)
        if (a.name == o.analysis) row.outputs[k] = measure(o.quantity, a, run);
      if (!std::isfinite(row.outputs[k]))
        throw std::domain_error("output '" + o.text + "' is not a finite number");
    }
    for (const Check& c : run.checks) {
      const auto at = std::find(plan_.checkNames.begin(), plan_.checkNames.end(), c.name);
      if (at == plan_.checkNames.end()) continue;
      const std::size_t k = std::size_t(at - plan_.checkNames.begin());
      row.checks[k] = c.computed;
      row.passed[k] = c.pass() ? 1 : 0;
    }
    row.cost.measure += clock.lap();
  } catch (const std::bad_alloc&) {
    row.status = kOutOfMemory;
  } catch (const std::exception& e) {  // DeckError, DeckSolveError and the core's own
    row.status = rowStatusText(e.what());
  }
  if (!row.ok()) {  // nothing half-measured: a failed point has no values
    std::fill(row.outputs.begin(), row.outputs.end(), kMissing);
    std::fill(row.checks.begin(), row.checks.end(), kMissing);
    std::fill(row.passed.begin(), row.passed.end(), -1);
  }
  return row;
}

}  // namespace beamrotor

#include "problems/run/DeckRunner.hpp"

#include <cmath>
#include <mutex>
#include <new>
#include <optional>
#include <span>
#include <stdexcept>
#include <variant>

#include "fem/assembly/ParallelParts.hpp"
#include "fem/assembly/Recovery.hpp"
#include "fem/assembly/SolutionPolynomials.hpp"
#include "fem/modal/BaseMotion.hpp"
#include "fem/modal/Modal.hpp"
#include "fem/modal/ResponseSpectrum.hpp"
#include "fem/solvers/Errors.hpp"
#include "fem/stability/Buckling.hpp"
#include "fem/stability/Prestressed.hpp"
#include "fem/stability/SecondOrder.hpp"
#include "fem/static/Static.hpp"
#include "fem/timing/Stopwatch.hpp"
#include "problems/deck/DeckReader.hpp"
#include "problems/deck/ShownFieldUnit.hpp"
#include "problems/deck/study/SweepOption.hpp"
#include "problems/deck/parse/Expression.hpp"
#include "problems/deck/parse/Field.hpp"
#include "problems/deck/parse/Units.hpp"
#include "problems/run/AdequateModel.hpp"
#include "problems/run/Measure.hpp"
#include "problems/run/DisplacementWarning.hpp"
#include "problems/run/JournalGravityLoads.hpp"
#include "problems/run/ModelBuilder.hpp"
#include "problems/run/RunCrankSlider.hpp"
#include "problems/run/RunMovingLoad.hpp"
#include "problems/run/OneWayStatics.hpp"
#include "problems/run/OverRefinementWarning.hpp"
#include "problems/run/Overloaded.hpp"
#include "problems/run/RunRotor.hpp"
#include "problems/run/RunTorsion.hpp"
#include "problems/run/RunTransient.hpp"
#include "problems/run/SweepRefinement.hpp"
#include "problems/run/UntrustedStatics.hpp"

namespace beamrotor {

namespace {

/// A combination's solution: the factored sum of its cases' displacements and reactions
/// (every case has the same supports, so their reactions line up), the hinge rotations
/// recovered under its loading, the factored sum of the cases', and its polynomials along the
/// elements, the factored sum of the cases'.
CaseOutcome combinationOf(const DeckCombination& k, const Model& model,
                          std::span<const CaseOutcome> cases) {
  Stopwatch clock;
  CaseOutcome out{k.name, true, k.factors, nullptr, {}, {}, nullptr};
  std::vector<std::pair<std::shared_ptr<const Loading>, double>> parts;
  std::vector<std::pair<std::shared_ptr<const SolutionPolynomials>, double>> polynomials;
  StaticResult& r = out.statics;
  const StaticResult& first = cases.front().statics;
  r.displacement = NodalField::Zero(first.displacement.rows(), first.displacement.cols());
  r.reactions = first.reactions;
  for (ReactionComponent& c : r.reactions) c.value = 0;
  r.elementForces = first.elementForces;
  for (ReactionComponent& c : r.elementForces) c.value = 0;
  for (const auto& [name, factor] : k.factors)
    for (const CaseOutcome& c : cases)
      if (c.name == name) {
        parts.emplace_back(c.loading, factor);
        polynomials.emplace_back(c.polynomials, factor);
        r.displacement += factor * c.statics.displacement;
        for (std::size_t i = 0; i < r.reactions.size(); ++i)
          r.reactions[i].value += factor * c.statics.reactions[i].value;
        for (std::size_t i = 0; i < r.elementForces.size(); ++i)
          r.elementForces[i].value += factor * c.statics.elementForces[i].value;
        r.roundOff = std::max(r.roundOff, c.statics.roundOff);
      }
  out.loading = std::make_shared<const Loading>(Loading::combination(parts));
  out.polynomials = std::make_shared<const SolutionPolynomials>(std::move(polynomials));
  r.hinges = hingeRotations(out.on(model));
  r.activeSetIterations = 1;
  r.rcond = first.rcond;
  r.solver = first.solver;
  r.size = first.size;
  r.time.total = clock.lap();
  return out;
}

/// The deck's own loads and each load case as loadings of the one model, all solved with one
/// factorisation of K (one more right-hand side each), then each combination as the factored
/// sum of its cases.
StaticOutcome solveWithCases(const Deck& deck, const Model& model, const StaticOptions& options) {
  StaticOutcome statics;
  std::vector<CaseOutcome>& out = statics.cases;
  out.reserve(deck.loadCases.size() + deck.combinations.size());  // `cases` below stays valid
  std::vector<const Loading*> loadings{nullptr};  // the model's own loads first
  for (const DeckLoadCase& lc : deck.loadCases) {
    out.push_back({lc.name, false, {},
                   std::make_shared<const Loading>(loadingOf(deck, model, lc.loads)), {}, {},
                   nullptr});
    loadings.push_back(out.back().loading.get());
  }
  std::vector<StaticResult> results = solveLoadings(model, loadings, options);
  statics.statics = std::move(results.front());
  for (std::size_t i = 1; i < results.size(); ++i) out[i - 1].statics = std::move(results[i]);
  // With combinations, each case's polynomials along the elements, recovered once: each
  // combination's are then their factored sum.
  if (!deck.combinations.empty())
    for (CaseOutcome& c : out) {
      Stopwatch clock;
      c.polynomials = std::make_shared<const SolutionPolynomials>(c.on(model));
      c.statics.time.total += clock.lap();
    }
  const std::span<const CaseOutcome> cases(out.data(), out.size());
  for (const DeckCombination& k : deck.combinations) out.push_back(combinationOf(k, model, cases));
  for (CaseOutcome& c : out)
    if (auto w = displacementWarning(model, c.statics)) c.warnings.push_back(*w);
  return statics;
}

/// Solves analysis a of deck on model; `oneWay`, when the deck has one-way members, is the
/// settled static solution of that model (the reader admits only linear statics then).
AnalysisOutcome solve(const Deck& deck, const DeckAnalysis& a, const Model& model,
                      RunCache* cache, const OneWaySolution* oneWay) {
  AnalysisOutcome out;
  out.type = a.type();
  out.name = a.name;
  try {
    out.result = std::visit(
        Overloaded{
            [&](const StaticSpec& spec) -> AnalysisResult {
              if (spec.secondOrder) return solveSecondOrder(model);
              StaticOptions options;
              if (cache) options.reuse = &cache->statics;
              // Load cases share the factorisation of the deck's own loads (no contacts then:
              // the reader refuses cases with contacts).
              StaticOutcome statics = oneWay ? StaticOutcome{oneWay->result, {}}
                                      : deck.loadCases.empty()
                                          ? StaticOutcome{solveStatic(model, options), {}}
                                          : solveWithCases(deck, model, options);
              // With load cases and an empty `loads:` (cases refuse prescribed support values)
              // the deck's own solution is the unloaded one.
              statics.ownLoads = !(deck.loads.empty() && !deck.loadCases.empty());
              if (!spec.acceptRoundOff) {
                if (statics.ownLoads) refuseUntrustedStatics(deck, model, statics.statics);
                for (const CaseOutcome& c : statics.cases)
                  refuseUntrustedStatics(deck, model, c.statics,
                                         (c.combination ? "combination " : "load case ") + c.name);
              }
              if (auto w = overRefinementWarning(model, statics.statics)) out.warnings.push_back(*w);
              if (auto w = displacementWarning(model, statics.statics)) out.warnings.push_back(*w);
              return statics;
            },
            [&](const BucklingSpec& spec) -> AnalysisResult {
              BucklingOptions options;
              options.count = spec.modes;
              options.reversed = spec.reversed;
              BucklingResult buckling = solveBuckling(model, options);
              out.warnings = buckling.warnings;
              return buckling;
            },
            [&](const ModalSpec& spec) -> AnalysisResult {
              ModalOptions options;
              options.modes = spec.modes;
              options.shift = spec.shift;
              ModalResult modal = spec.prestressed ? solvePrestressedModes(model, options)
                                                   : solveModes(model, options);
              out.warnings.insert(out.warnings.end(), modal.warnings.begin(), modal.warnings.end());
              return modal;
            },
            [&](const ResponseSpectrumSpec& spec) -> AnalysisResult {
              ResponseSpectrumResult r = solveResponseSpectrum(model, spec.spectrum, spec.options);
              out.warnings = r.warnings;
              return r;
            },
            [&](const BaseMotionSpec& spec) -> AnalysisResult {
              return solveBaseMotion(model, spec.options);
            },
            [&](const TransientSpec& spec) -> AnalysisResult {
              return runTransient(deck, spec.run, model);
            },
            [&](const CrankSliderSpec& spec) -> AnalysisResult {
              return runCrankSlider(spec.mechanism);
            },
            [&](const MovingLoadSpec& spec) -> AnalysisResult {
              return runMovingLoad(spec, model);
            },
            [&](const TorsionSpec& spec) -> AnalysisResult {
              TorsionOutcome torsion = runTorsion(deck, spec);
              out.warnings = torsion.modes.warnings;
              return torsion;
            },
            [&](const RotorFamily&) -> AnalysisResult {
              AnalysisResult rotor = solveRotorAnalysis(deck, a, model);
              out.warnings = rotorWarnings(rotor);
              return rotor;
            },
        },
        a.kind);
  } catch (const DeckError&) {
    throw;  // bad input only the model could reveal (an unstable explicit step)
  } catch (const std::bad_alloc&) {
    throw DeckSolveError(deck.path, a.place, kOutOfMemory);
  } catch (const std::exception& e) {
    // SolveError and UnsupportedStructure say what is wrong; anything else the core throws
    // while solving is reported the same way rather than escaping as a crash.
    throw DeckSolveError(deck.path, a.place, e.what());
  }
  return out;
}

Check evaluate(const DeckCheck& k, const RunResult& run, const Model& model) {
  Check c;
  c.name = k.name;
  c.quantity = k.quantity.text;
  c.reference = k.reference;
  c.tolerance = k.tolerance;
  c.paper = k.paper;
  c.reason = k.reason;
  for (const AnalysisOutcome& a : run.analyses) {
    if (a.name != k.analysis) continue;
    // A section's figures are the same in every case.
    if (k.loadCase.empty() || k.quantity.kind == Quantity::Kind::sectionProperty) {
      c.computed = measure(k.quantity, a, run);
      continue;
    }
    c.quantity += " (case " + k.loadCase + ")";
    for (const CaseOutcome& lc : casesOf(a))
      if (lc.name == k.loadCase) c.computed = measureStatic(k.quantity, lc.statics, lc.on(model));
  }
  // A NaN compares false with everything: it must never reach a pass, a table or the
  // accuracy search's convergence test.
  if (!std::isfinite(c.computed))
    throw std::domain_error("the computed value of '" + k.quantity.text + "' is " +
                            (std::isnan(c.computed) ? "not a number" : "infinite"));
  return c;
}

}  // namespace

RunResult runDeck(const Deck& deck, RunCache* cache) {
  // Plain journals loaded by the rotor's weight: their tables first, for every later reader.
  if (needsJournalLoads(deck)) return runDeck(withJournalLoads(deck), cache);
  if (deck.accuracy) {
    RunResult adequate = runAdequateModel(deck);
    adequate.warnings = deck.warnings;
    return adequate;
  }
  Stopwatch clock;
  RunResult run;
  run.warnings = deck.warnings;
  run.deckPath = deck.path;
  run.deckName = deck.stem;
  run.parameters = deck.parameters;
  run.reported = deck.reported;
  run.catalogSections = deck.catalogSections;
  for (const auto& [name, dimension] : deck.dimensions)
    run.units.emplace_back(name, siUnitOf(dimension));
  run.dimension = deck.dimension;

  // 1. The model, with its slack members out of action when it has one-way members.
  const std::optional<OneWaySolution> oneWay = solveOneWayMembers(deck);
  std::shared_ptr<const Model> model = oneWay ? oneWay->model : buildModel(deck);
  run.model = model;
  run.modelSeconds = clock.lap();

  // 2. The analyses, in deck order.
  for (const DeckAnalysis& a : deck.analyses)
    run.analyses.push_back(solve(deck, a, *model, cache, oneWay ? &*oneWay : nullptr));
  run.analysesSeconds = clock.lap();

  // 3. The checks that apply to these parameter values.
  for (const DeckCheck& k : deck.checks) {
    if (!k.applicable) {
      run.skippedChecks.push_back(k.name);
      continue;
    }
    try {
      run.checks.push_back(evaluate(k, run, *model));
    } catch (const std::exception& e) {
      // The reader validated names and mode counts; what remains is e.g. ARPACK returning
      // fewer modes than asked.
      throw DeckSolveError(deck.path, k.place, "check '" + k.name + "': " + e.what());
    }
  }
  run.checksSeconds = clock.lap();
  run.seconds = run.modelSeconds + run.analysesSeconds + run.checksSeconds;
  return run;
}

SweepResult runSweep(const DeckSource& source, const std::vector<ParameterOverride>& overrides,
                     const Deck& base, const SweepProgress& progress,
                     const DeckAdjustment& adjust) {
  // `refine:` adds values where the result changes fast and around its peaks, to the deck's
  // own sweep (a --sweep from the command line, placed at no line, is solved as given). Read
  // before the first run, so that a bad one fails at once.
  std::optional<DeckSweepRefinement> refine;
  if (base.sweep->place.line > 0) refine = readSweepRefinement(source, base);
  SweepResult sweep;
  sweep.parameter = base.sweep->parameter;
  sweep.unit = bareUnitName(parameterUnit(base, sweep.parameter));
  sweep.values = base.sweep->values;
  // Every value reads the deck again: what an earlier reading evaluated comes from the
  // memo's byte code (the same deck, bit for bit), as a design study's points do. Re-parsing
  // every expression in every system of units was a quarter of the MO-10 sweep's solve.
  // Each value is a run of its own, the same to the bit on any thread, so the values of one
  // batch (the deck's, then each refinement's) run side by side, one per core, each core's
  // readings with a memo of its own (a memo serves one thread).
  const int cores = usableCores();
  std::vector<ExpressionMemo> memos(std::size_t(std::max(cores, 1)));
  const auto runValue = [&](double value, ExpressionMemo& memo) {
    std::vector<ParameterOverride> withValue = overrides;
    withValue.push_back({sweep.parameter, value, sweep.parameter + "=" + formatNumber(value)});
    const std::string at = "with " + sweep.parameter + " = " + formatNumber(value) + " (sweep): ";
    try {
      Deck deck = readDeck(source, withValue, memo);
      if (adjust) adjust(deck);
      return runDeck(deck);
    } catch (const DeckError& e) {
      throw DeckError(e.file(), e.place(), at + e.message());
    } catch (const DeckSolveError& e) {
      throw DeckSolveError(e.file(), e.place(), at + e.message());
    }
  };
  std::mutex progressShown;
  int done = 0;
  const int total = int(sweep.values.size());
  sweep.runs = resultsSideBySide(total, cores, [&](int i, int core) {
    RunResult run = runValue(sweep.values[std::size_t(i)], memos[std::size_t(core)]);
    const std::lock_guard<std::mutex> lock(progressShown);
    if (progress) progress(++done, total);
    return run;
  });
  const auto runValues = [&](const std::vector<double>& values) {
    return resultsSideBySide(int(values.size()), cores, [&](int i, int core) {
      return runValue(values[std::size_t(i)], memos[std::size_t(core)]);
    });
  };
  if (refine && refine->parameter == sweep.parameter) refineSweep(sweep, *refine, runValues);
  return sweep;
}

}  // namespace beamrotor

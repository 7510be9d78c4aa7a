#include "problems/converge/ConvergeStudy.hpp"

#include <algorithm>
#include <cmath>

#include "fem/timing/Median.hpp"
#include "problems/converge/ConvergenceRates.hpp"
#include "problems/deck/DeckReader.hpp"
#include "problems/run/DeckRunner.hpp"
#include "problems/run/Measure.hpp"

namespace beamrotor {

namespace {

/// The quantity, the analysis it reads and the check giving its closed form (if any).
struct Target {
  Quantity quantity;
  const DeckAnalysis* analysis = nullptr;
  const DeckCheck* check = nullptr;
};

Target resolveTarget(const Deck& deck, const std::string& text) {
  const DeckPlace option{0, 0, "--quantity"};
  Target t;
  for (const DeckCheck& k : deck.checks)
    if (k.applicable && (text.empty() || k.quantity.text == text)) {
      t.check = &k;
      break;
    }
  if (text.empty() && !t.check)
    throw DeckError(deck.path, option, "the deck has no check to take a quantity from; name one");
  try {
    t.quantity = t.check ? t.check->quantity : parseQuantity(text);
  } catch (const std::invalid_argument& e) {
    throw DeckError(deck.path, option, e.what());
  }
  for (const DeckAnalysis& a : deck.analyses)
    if (t.check ? a.name == t.check->analysis : t.quantity.readsFrom(a.type)) {
      t.analysis = &a;
      break;
    }
  if (!t.analysis)
    throw DeckError(deck.path, option, "no analysis of the deck gives '" + t.quantity.text + "'");
  if (t.analysis->type != "static" && t.analysis->type != "modal")
    throw DeckError(deck.path, option,
                    "'" + t.quantity.text + "' reads a " + t.analysis->type +
                        " analysis; converge studies static and modal quantities");
  return t;
}

/// The deck reduced to the one analysis, without checks, sweep or accuracy target.
Deck studyDeck(const Deck& deck, const Target& t) {
  Deck d = deck;
  d.analyses = {*t.analysis};
  d.checks.clear();
  d.sweep.reset();
  d.accuracy.reset();  // the study chooses the meshes itself
  return d;
}

const SolveTimings& timingsOf(const AnalysisOutcome& a) {
  return a.statics ? a.statics->time : a.modal->time;
}
const SystemSize& sizeOf(const AnalysisOutcome& a) {
  return a.statics ? a.statics->size : a.modal->size;
}

/// Solves one level, repeating short runs; the quantity is taken from the first run.
ConvergeLevel solveLevel(const Deck& deck, const Quantity& q, int level, int repeats) {
  ConvergeLevel out;
  out.level = level;
  std::vector<double> assembly, factor, solve, total;
  for (int r = 0; r < repeats; ++r) {
    const RunResult run = runDeck(deck);
    const AnalysisOutcome& a = run.analyses.front();
    if (r == 0) {
      try {
        out.value = measure(q, a, *run.model);
      } catch (const std::logic_error& e) {  // e.g. a point the deck does not name
        throw DeckError(deck.path, DeckPlace{0, 0, "--quantity"}, e.what());
      }
      out.elements = sizeOf(a).elements;
      out.dofs = sizeOf(a).freeDofs;
    }
    const SolveTimings& t = timingsOf(a);
    assembly.push_back(t.assembly);
    factor.push_back(t.factor);
    solve.push_back(t.solve);
    total.push_back(t.total);
    if (t.total >= kShortRunSeconds) break;
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

ConvergeStudy runConvergence(const Deck& deck, const ConvergeOptions& options) {
  // 1. What to measure and against what.
  const Target t = resolveTarget(deck, options.quantity);
  if (options.levels < (t.check ? 2 : 3) || options.levels > 16)
    throw DeckError(deck.path, DeckPlace{0, 0, "--levels"},
                    std::string("must be from ") + (t.check ? "2" : "3") +
                        " (3 to extrapolate without a closed form) to 16, got " +
                        std::to_string(options.levels));
  ConvergeStudy study;
  study.deckPath = deck.path;
  study.deckName = deck.stem;
  study.quantity = t.quantity.text;
  study.analysis = t.analysis->name;
  if (t.check) study.check = t.check->name;

  // 2. Every method on every level, the finest within what a deck may ask for.
  const Deck base = studyDeck(deck, t);
  Deck finest = base;
  refineMesh(finest, options.levels - 1);
  double elements = 0;
  for (const DeckSegment& s : finest.segments) elements += s.elementEstimate();
  if (elements > kMaxElements)
    throw DeckError(deck.path, DeckPlace{0, 0, "--levels"},
                    "the finest mesh would have " + std::to_string(std::llround(elements)) +
                        " elements, more than the " + std::to_string(kMaxElements) +
                        " a deck may have; use fewer levels");
  for (const ConvergeMethod& method : convergeMethods(t.analysis->type != "static")) {
    ConvergeSeries series;
    series.method = method;
    for (int level = 0; level < options.levels; ++level) {
      Deck d = base;
      useMethod(method, d);
      refineMesh(d, level);
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

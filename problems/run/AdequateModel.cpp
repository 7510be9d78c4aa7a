#include "problems/run/AdequateModel.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <optional>

#include "fem/timing/Stopwatch.hpp"
#include "problems/deck/DeckReader.hpp"
#include "problems/deck/parse/Field.hpp"
#include "problems/deck/structure/Formulations.hpp"
#include "problems/run/ConvergeMethods.hpp"
#include "problems/run/DeckRunner.hpp"
#include "problems/run/UntrustedStatics.hpp"

namespace beamrotor {

namespace {

/// The largest relative difference between the checked values of two runs of the deck.
double largestChange(const RunResult& a, const RunResult& b) {
  double change = 0;
  for (std::size_t i = 0; i < a.checks.size() && i < b.checks.size(); ++i) {
    const double scale = std::max({std::abs(a.checks[i].computed), std::abs(b.checks[i].computed),
                                   std::abs(a.checks[i].reference)});
    const double diff = std::abs(a.checks[i].computed - b.checks[i].computed);
    change = std::max(change, scale > 0 ? diff / scale : diff);
  }
  return change;
}

/// A level of the search: the deck with 2^level elements on every segment.
Deck atLevel(const Deck& deck, int level) {
  Deck d = acceptingRoundOff(deck);  // the search measures round-off itself
  d.accuracy.reset();
  for (DeckSegment& s : d.segments) {
    s.elements = 1 << level;
    s.size = 0;
  }
  for (TrainShaft& shaft : d.train.shafts)
    for (Segment& s : shaft.segments) {
      s.elements = 1 << level;
      s.targetSize = 0;
    }
  return d;
}

struct MeshChoice {
  RunResult run;
  int level = 0;
  double error = 0;  ///< change from the next coarser level
};

/// The largest measured round-off error of the run's static solutions (0 without any).
double roundOffOf(const RunResult& run) {
  double largest = 0;
  for (const AnalysisOutcome& a : run.analyses)
    if (const StaticResult* s = staticsOf(a)) largest = std::max(largest, s->roundOff);
  return largest;
}

/// Step 1: the first level agreeing with the one before to within the target. A level too
/// coarse for an analysis (fewer dofs than modes asked) counts as not yet there. Refining
/// stops, and the search fails naming the `accuracy` field, once round-off starts to dominate:
/// a static solution's measured round-off error above the target, a solve that fails after a
/// coarser one succeeded, or successive changes that stop falling (from the fourth level on,
/// past the coarse meshes' irregular start).
MeshChoice searchMesh(const Deck& deck, double target, double& seconds) {
  const auto fail = [&](const std::string& why) {
    throw DeckSolveError(deck.path, deck.accuracy->place,
                         formatNumber(target) + " not reached: " + why);
  };
  // The finest level within the element cap a deck has (so within its memory estimate).
  int finest = 0;
  while (finest < kMaxAdequateLevel &&
         double(deck.segments.size()) * double(2 << finest) <= double(kMaxElements))
    ++finest;
  std::optional<RunResult> previous;
  std::optional<double> previousChange;
  for (int level = 0; level <= finest; ++level) {
    const std::string perSegment = std::to_string(1 << level) + " elements per segment";
    Stopwatch clock;
    std::optional<RunResult> run;
    try {
      run = runDeck(atLevel(deck, level));
    } catch (const DeckSolveError& e) {
      if (!previous && level == finest) throw;  // no mesh solves it: the solve's own error
      if (previous)
        fail("the solve with " + perSegment +
             " failed, refining further cannot help: " + e.message());
    }
    seconds += clock.lap();
    if (!run) continue;
    if (const double roundOff = roundOffOf(*run); roundOff > target)
      fail("with " + perSegment +
           " the static solution's round-off alone, bounded by "
           "measurement at " +
           formatNumber(roundOff) + ", exceeds the target, and it only grows with finer meshes");
    // A point inside a segment already splits it: the same mesh twice would agree trivially.
    const auto elements = [](const RunResult& r) { return r.model->elements().size(); };
    if (previous && elements(*run) > elements(*previous)) {
      const double change = largestChange(*run, *previous);
      if (change <= target) return {std::move(*run), level, change};
      if (previousChange && level >= 3 && change >= *previousChange)
        fail("successive meshes stopped converging at " + perSegment + " (they differ by " +
             formatNumber(change) + ", by " + formatNumber(*previousChange) +
             " one level coarser): round-off dominates from there; about " +
             formatNumber(std::min(change, *previousChange)) + " is reachable");
      previousChange = change;
    }
    previous = std::move(run);
  }
  fail("successive meshes still differ by more than that with " +
       std::to_string(1 << finest) + " elements per segment (the most the cap of " +
       std::to_string(kMaxElements) + " elements allows)");
  return {};
}

/// Largest relative difference of the two-dof frequencies of the run's rigid-body analysis
/// from the two lowest frequencies of its first modal analysis; none without both.
std::optional<double> rigidBodyError(const RunResult& run) {
  const RigidBodyOutcome* rigid = nullptr;
  const ModalResult* modal = nullptr;
  for (const AnalysisOutcome& a : run.analyses) {
    if (!rigid) rigid = resultOf<RigidBodyOutcome>(a);
    if (!modal) modal = resultOf<ModalResult>(a);
  }
  if (!rigid || !modal || modal->modes.size() < 2) return std::nullopt;
  double largest = 0;
  for (int i = 0; i < 2; ++i) {
    const double fe = modal->modes[i].frequencyHz;
    const double twoDof = rigid->modes[i].k / (2 * std::numbers::pi);
    largest = std::max(largest, std::abs(twoDof - fe) / fe);
  }
  return largest;
}

int dofsOf(const Deck& deck, const RunResult& run) {
  return run.model->nodeCount() * deck.dofs.size();
}

}  // namespace

RunResult runAdequateModel(const Deck& deck) {
  const double target = deck.accuracy->target;
  AdequateChoice choice;
  choice.target = target;
  choice.deckFormulation = formulationName(deck.segments.front().options.theory);

  // 1. The mesh for the deck's own beam theory.
  MeshChoice chosen = searchMesh(deck, target, choice.searchSeconds);
  Deck chosenDeck = atLevel(deck, chosen.level);
  choice.meshError = chosen.error;
  choice.estimatedError = chosen.error;

  // 2. Euler-Bernoulli instead, when the deck has shear-deformable beams.
  const bool shear = std::any_of(deck.segments.begin(), deck.segments.end(), [](const auto& s) {
    return s.options.theory != BeamTheory::eulerBernoulli;
  });
  if (shear) {
    Deck eb = deck;
    useMethod({"eb", "", BeamTheory::eulerBernoulli, deck.beam.mass}, eb);
    for (std::size_t i = 0; i < eb.segments.size(); ++i)
      eb.segments[i].options.mass = deck.segments[i].options.mass;
    MeshChoice ebChoice = searchMesh(eb, target, choice.searchSeconds);
    choice.shearContribution = largestChange(ebChoice.run, chosen.run);
    const double ebError = ebChoice.error + *choice.shearContribution;
    if (ebError <= target) {
      chosen = std::move(ebChoice);
      chosenDeck = atLevel(eb, chosen.level);
      choice.meshError = chosen.error;
      choice.estimatedError = ebError;
    }
  }

  // 3. The chosen model and the deck's own mesh, each solved once more for their cost.
  Deck fixed = acceptingRoundOff(deck);  // only timed: its round-off is no verdict here
  fixed.accuracy.reset();
  const RunResult fixedRun = runDeck(fixed);
  RunResult run = runDeck(chosenDeck);
  choice.formulation = formulationName(chosenDeck.segments.front().options.theory);
  choice.elementsPerSegment = 1 << chosen.level;
  choice.elements = int(run.model->elements().size());
  choice.dofs = dofsOf(deck, run);
  choice.seconds = run.seconds;
  choice.deckElements = int(fixedRun.model->elements().size());
  choice.deckDofs = dofsOf(deck, fixedRun);
  choice.deckSeconds = fixedRun.seconds;
  choice.searchSeconds += run.seconds;

  // 4. The rigid body on its springs, where the deck compares one.
  choice.rigidBodyError = rigidBodyError(run);
  choice.rigidBodyAdequate =
      choice.rigidBodyError && *choice.rigidBodyError + choice.meshError <= target;
  run.adequate = choice;
  return run;
}

}  // namespace beamrotor

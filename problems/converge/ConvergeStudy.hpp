// `beamrotor converge`: one deck quantity computed on a sequence of meshes (each level halves
// every element) with each element formulation, or for a transient quantity on a sequence of
// time steps (each level halves dt) with the deck's own scheme, timed stage by stage, and its
// error against the deck's closed form, or against a Richardson-extrapolated limit where the
// deck has none.
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "problems/deck/Deck.hpp"
#include "problems/run/ConvergeMethods.hpp"

namespace beamrotor {

struct ConvergeOptions {
  /// A deck quantity phrase; empty: the first of the deck's quantities that changes with the
  /// discretisation (its applicable checks in order, then each analysis' lowest frequency,
  /// largest stress or first history), see runConvergence.
  std::string quantity;
  int levels = 5;  ///< meshes: the deck's own (level 0) and levels - 1 refinements
  /// Runs timed per level when one run is short (< kShortRunSeconds); times are medians.
  int repeats = 3;
};

/// A solve shorter than this (s) is repeated so that its times are medians.
inline constexpr double kShortRunSeconds = 0.2;

/// One mesh of one method.
struct ConvergeLevel {
  int level = 0;
  int elements = 0;
  int dofs = 0;   ///< free dofs
  int steps = 0;  ///< time steps (time-step studies; 0 in mesh studies)
  double assembly = 0, factor = 0, solve = 0, total = 0;  ///< s, medians over the runs
  int runs = 1;
  double value = 0;  ///< the quantity
  double error = 0;  ///< |value - reference| / |reference| (absolute when reference is 0)
  std::optional<double> order;  ///< observed order against the previous level
};

struct ConvergeSeries {
  ConvergeMethod method;
  std::vector<ConvergeLevel> levels;
  double reference = 0;       ///< the closed form, or this series' extrapolated limit
  bool extrapolated = false;  ///< reference is a Richardson estimate (no closed form)
  std::optional<double> extrapolationOrder;  ///< the order the extrapolation found
  /// Why the method stopped before the last level (the solver's message), empty if it did
  /// not: a method that fails on fine meshes (e.g. the locking element's conditioning) ends
  /// its series there, the others go on.
  std::string failure;
};

struct ConvergeStudy {
  std::string deckPath, deckName;
  std::string quantity;    ///< as written, e.g. "frequency 1"
  FieldUnit unit;          ///< of the values and references (referenceUnit of the quantity)
  std::string analysis;    ///< the deck analysis it reads
  std::string check;       ///< the check giving the closed form; empty when there is none
  std::string refinement;  ///< "mesh" or "time step"
  std::string choice;      ///< how the quantity was chosen, for the user
  std::vector<ConvergeSeries> series;  ///< one per method
};

/// Runs the study on a read deck (its sweep ignored). Without a quantity it takes the first
/// candidate whose value changes by more than round-off when the deck's own discretisation is
/// refined once (a reaction of a statically determinate beam or a rigid-body property does not;
/// a quantity of a rigid-body analysis is no candidate), or the first candidate when none
/// does, saying so. Throws DeckError (naming the option, e.g. "--quantity") for a quantity the
/// deck cannot give or too few levels, and DeckSolveError when a solve fails.
ConvergeStudy runConvergence(const Deck& deck, const ConvergeOptions& options);

/// Why a study of the deck would be meaningless ("nothing to converge: ..."), when none of its
/// analyses depends on a mesh or a time step (a crank-slider, a rigid body given by its own
/// inputs: FORMAT.md "Mechanisms without a model"); nullopt when there is something to refine.
/// runConvergence refuses such a deck with this message.
std::optional<std::string> nothingToConverge(const Deck& deck);

}  // namespace beamrotor

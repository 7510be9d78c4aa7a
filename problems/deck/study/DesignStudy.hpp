// A design study: a deck solved at many points of its parameter space, each point recording
// the outputs the user names, the deck's checks and a status. The points come from a grid
// (every combination of each parameter's values) or from sampling (random or Latin-hypercube)
// distributions given per parameter. Read from the deck's `study:` block and from the
// `beamrotor study` options (problems/deck/FORMAT.md, section Design studies).
#pragma once

#include <cstdint>
#include <limits>
#include <optional>
#include <string>
#include <vector>

#include "problems/deck/Deck.hpp"
#include "problems/deck/parse/DeckSource.hpp"
#include "problems/deck/Quantity.hpp"

namespace beamrotor {

/// How a sampled parameter is distributed; values outside [lower, upper] never occur (the
/// distribution is truncated there, not clipped).
struct StudyDistribution {
  enum class Kind { uniform, normal, lognormal };
  Kind kind = Kind::uniform;
  /// uniform: the interval's ends; normal: mean and standard deviation; lognormal: the median
  /// (in the parameter's unit) and the standard deviation of its natural logarithm.
  double first = 0, second = 0;
  double lower = -std::numeric_limits<double>::infinity();
  double upper = std::numeric_limits<double>::infinity();
};

/// One varied parameter: grid values, or a distribution to sample.
struct StudyParameter {
  std::string name;
  std::vector<double> values;                     ///< grid
  std::optional<StudyDistribution> distribution;  ///< sampling
  DeckPlace place;
};

/// A quantity to record at every point (any check quantity), optionally with a limit on its
/// value, upper (`<=`, `limit:`) or lower (`>=`, `lower_limit:`), whose violations the
/// summary counts.
struct StudyOutput {
  std::string text;      ///< as written, e.g. "stress max"; its column's name
  Quantity quantity;     ///< parsed and resolved against the deck
  std::string analysis;  ///< the analysis it reads
  std::optional<double> limit;
  DeckPlace place;
  bool lowerLimit = false;  ///< the limit is a least value (the value must stay at or above it)
  /// Whether `value` lies beyond the limit (false without one).
  bool violates(double value) const {
    return limit && (lowerLimit ? value < *limit : value > *limit);
  }
};

enum class StudySampling { grid, random, latinHypercube };

struct DesignStudySpec {
  std::vector<StudyParameter> parameters;
  StudySampling sampling = StudySampling::grid;
  long long samples = 0;    ///< random and Latin-hypercube: how many points
  std::uint64_t seed = 1;   ///< the engine's seed (std::mt19937_64)
  std::vector<StudyOutput> outputs;
  /// Points in all: the product of the grid's value counts, or `samples`.
  long long points() const;
};

/// The study options of the command line, as typed (each replaces the deck's `study:` part).
struct StudyCommandLine {
  std::vector<std::string> sweeps;   ///< "NAME=FROM:TO:STEPS" or "NAME=V1,V2": grid axes
  std::vector<std::string> samples;  ///< "NAME=normal(MEAN,SD[,LOWER,UPPER])" and the like
  std::vector<std::string> outputs;  ///< "QUANTITY", "QUANTITY <= LIMIT" or "QUANTITY >= LIMIT"
  std::string sampling;              ///< "random" or "latin-hypercube"; "": the deck's or random
  std::optional<long long> count;    ///< --samples
  std::optional<std::uint64_t> seed;
};

/// Most points a study may have.
inline constexpr long long kMaxStudyPoints = 100000000;

/// The study of `deck` (read from `source` with the user's overrides): its `study:` block,
/// with what the command line gives replacing the block's parts; without either, the deck's
/// `sweep:` as a one-parameter grid. Outputs default to the quantities of the deck's checks.
/// Throws DeckError naming the deck and the field or option at fault.
DesignStudySpec readDesignStudy(const DeckSource& source, const Deck& deck,
                                const StudyCommandLine& commandLine);

}  // namespace beamrotor

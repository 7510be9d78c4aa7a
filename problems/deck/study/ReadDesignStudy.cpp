// Reading a design study (DesignStudy.hpp): the deck's `study:` block and the `beamrotor
// study` options, each value checked against the parameter it varies and each output against
// the deck, as a check's quantity is.
#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "problems/deck/DeckReader.hpp"
#include "problems/deck/FieldUnits.hpp"
#include "problems/deck/study/DesignStudy.hpp"
#include "problems/deck/study/ReadDeckContext.hpp"
#include "problems/deck/parse/Expression.hpp"
#include "problems/deck/parse/Field.hpp"
#include "problems/deck/parse/SceneFunctions.hpp"
#include "problems/deck/ReaderContext.hpp"
#include "problems/deck/parse/Suggest.hpp"
#include "problems/deck/study/SweepOption.hpp"

namespace beamrotor {

long long DesignStudySpec::points() const {
  if (sampling != StudySampling::grid) return samples;
  long long n = 1;
  for (const StudyParameter& p : parameters) {
    n *= (long long)p.values.size();
    if (n > kMaxStudyPoints) return kMaxStudyPoints + 1;  // no overflow on a huge grid
  }
  return n;
}

namespace {

const std::vector<std::string> kSamplingNames{"grid", "random", "latin-hypercube"};

/// The reader's context for the deck as read: study fields use its parameters, and outputs
/// resolve as checks do.
using StudyContext = ReadDeckContext;

std::vector<std::string> parameterNames(const Deck& deck) {
  std::vector<std::string> names;
  for (const auto& [name, v] : deck.parameters) names.push_back(name);
  return names;
}

/// Fails (through `fail`) unless `name` is a parameter of the deck and not yet varied.
template <class Fail>
void requireFreeParameter(const Deck& deck, const std::string& name,
                          const std::vector<StudyParameter>& taken, Fail&& fail) {
  const std::vector<std::string> names = parameterNames(deck);
  if (std::find(names.begin(), names.end(), name) == names.end())
    fail("no parameter '" + name + "' in this deck" + didYouMean(name, names) +
         " (parameters: " + joinNames(names) + ")");
  for (const StudyParameter& p : taken)
    if (p.name == name) fail("'" + name + "' is varied twice; give it once");
}

/// Fails unless the distribution's numbers describe one: a positive spread, ordered bounds
/// that leave it some probability, a positive median and lower bound for a lognormal.
template <class Fail>
void requireSensible(const StudyDistribution& d, Fail&& fail) {
  using Kind = StudyDistribution::Kind;
  if (d.kind == Kind::uniform && !(d.first < d.second))
    fail("a uniform distribution needs LOW < HIGH");
  if (d.kind != Kind::uniform && !(d.second > 0))
    fail(d.kind == Kind::normal ? "the standard deviation must be positive"
                                : "sigma (of the logarithm) must be positive");
  if (d.kind == Kind::lognormal && !(d.first > 0)) fail("a lognormal median must be positive");
  if (!(d.lower < d.upper)) fail("the lower bound must lie below the upper bound");
  // Bounds so far out that no double falls between them in probability leave nothing.
  const double scale = d.kind == Kind::uniform ? d.second - d.first : d.second;
  const double centre = d.kind == Kind::uniform ? (d.first + d.second) / 2 : d.first;
  if (d.kind == Kind::normal && (d.lower > centre + 30 * scale || d.upper < centre - 30 * scale))
    fail("the bounds leave the distribution no probability (more than 30 standard deviations "
         "from the mean)");
  if (d.kind == Kind::uniform && (d.lower >= d.second || d.upper <= d.first))
    fail("the bounds lie outside [LOW, HIGH]");
  if (d.kind == Kind::lognormal && d.upper <= 0) fail("the upper bound must be positive");
}

/// The arguments between the parentheses of "kind(a, b, c)", split at commas outside nested
/// parentheses (an argument may be an expression such as sqrt(2) mm).
std::vector<std::string> callArguments(const std::string& text, std::size_t open) {
  std::vector<std::string> args{""};
  int depth = 0;
  for (std::size_t i = open + 1; i + 1 < text.size(); ++i) {
    const char ch = text[i];
    if (ch == '(') ++depth;
    if (ch == ')') --depth;
    if (ch == ',' && depth == 0)
      args.emplace_back();
    else
      args.back() += ch;
  }
  return args;
}

StudyParameter parseSampleOption(const std::string& argument, const Deck& deck,
                                 const std::vector<StudyParameter>& taken) {
  const DeckPlace place{0, 0, "--sample " + argument};
  auto fail = [&](const std::string& why) { throw DeckError(deck.path, place, why); };
  const std::size_t eq = argument.find('=');
  const std::size_t open = argument.find('(');
  if (eq == std::string::npos || open == std::string::npos || open < eq ||
      argument.back() != ')')
    fail("expected NAME=uniform(LOW,HIGH), NAME=normal(MEAN,SD) or "
         "NAME=lognormal(MEDIAN,SIGMA), each optionally with ,LOWER,UPPER bounds");
  StudyParameter p;
  p.name = argument.substr(0, eq);
  p.place = place;
  requireFreeParameter(deck, p.name, taken, fail);
  const std::string kind = argument.substr(eq + 1, open - eq - 1);
  StudyDistribution d;
  if (kind == "uniform")
    d.kind = StudyDistribution::Kind::uniform;
  else if (kind == "normal")
    d.kind = StudyDistribution::Kind::normal;
  else if (kind == "lognormal")
    d.kind = StudyDistribution::Kind::lognormal;
  else
    fail("no distribution '" + kind + "'" +
         didYouMean(kind, {"uniform", "normal", "lognormal"}) +
         " (distributions: uniform, normal, lognormal)");
  const std::vector<std::string> args = callArguments(argument, open);
  if (args.size() != 2 && args.size() != 4)
    fail("expected 2 numbers, or 4 with the bounds, between the parentheses; got " +
         std::to_string(args.size()));
  auto value = [&](const std::string& text) {
    return parameterValueOption(text, p.name, deck, place);
  };
  d.first = value(args[0]);
  // A lognormal's sigma is the spread of the logarithm: a pure number.
  const auto pureNumber = [&](const std::string& text) {
    Amount a;
    try {
      a = ExpressionEvaluator().amount(text);
    } catch (const ExpressionError& e) {
      fail(e.what());
    }
    if (!a.anyDimension && !a.dimension.dimensionless())
      fail("sigma (of the logarithm) is a pure number, got '" + text + "'");
    return a.si;
  };
  d.second = d.kind == StudyDistribution::Kind::lognormal ? pureNumber(args[1]) : value(args[1]);
  if (args.size() == 4) {
    d.lower = value(args[2]);
    d.upper = value(args[3]);
  }
  requireSensible(d, fail);
  p.distribution = d;
  return p;
}

/// Resolves the output's quantity against the deck (names, analysis), failing at `at`.
void resolveOutput(const StudyContext& s, StudyOutput& o, const Field& at) {
  try {
    o.quantity = parseQuantity(o.text);
  } catch (const std::invalid_argument& e) {
    at.fail(e.what());
  }
  o.analysis = reader::resolveQuantity(s.c, o.quantity, at, std::nullopt, true);
}

StudyOutput parseOutputOption(const std::string& argument, const StudyContext& s) {
  const DeckPlace place{0, 0, "--output " + argument};
  StudyOutput o;
  o.place = place;
  const std::size_t le = argument.find("<="), ge = argument.find(">=");
  if (le != std::string::npos && ge != std::string::npos)
    throw DeckError(s.deck.path, place, "give one limit, <= LIMIT or >= LIMIT, not both");
  const std::size_t at = le != std::string::npos ? le : ge;
  o.lowerLimit = ge != std::string::npos;
  o.text = argument.substr(0, at);
  while (!o.text.empty() && o.text.back() == ' ') o.text.pop_back();
  try {
    if (at != std::string::npos) {
      // Read as the deck's `limit:` is, in the quantity's own unit.
      const auto limit = DeckTree::ofScalar(argument.substr(at + 2), s.deck.path);
      o.limit = Field::root(*limit).number(ExpressionEvaluator(),
                                           referenceUnit(parseQuantity(o.text)));
    }
    const auto typed = DeckTree::ofScalar(o.text, s.deck.path);
    resolveOutput(s, o, Field::root(*typed));
  } catch (const DeckError& e) {
    throw DeckError(s.deck.path, place, e.message());
  } catch (const ExpressionError& e) {
    throw DeckError(s.deck.path, place, e.what());
  } catch (const std::invalid_argument& e) {
    throw DeckError(s.deck.path, place, e.what());
  }
  return o;
}

/// One entry of `study: parameters:` (NAME: {values | from, to, steps | distribution ...}).
StudyParameter readParameter(const StudyContext& s, const std::string& name, const Field& f,
                             const std::vector<StudyParameter>& taken) {
  StudyParameter p;
  p.name = name;
  p.place = f.place();
  requireFreeParameter(s.deck, name, taken, [&](const std::string& why) { f.fail(why); });
  // Written with a unit or told by the fields it flows into: values with a unit must have it.
  const FieldUnit own = parameterUnit(s.deck, name);
  const auto value = [&](const Field& v) { return parameterValue(v, s.c.evaluator, name, own); };
  if (!f.isMap()) f.fail("expected a map such as {from: 0, to: 1, steps: 10}, got " + f.describe());
  if (auto kind = f.get("distribution")) {
    StudyDistribution d;
    const std::string k = kind->choice({"uniform", "normal", "lognormal"});
    auto bound = [&](const char* key, double& into) {
      if (auto b = f.get(key)) into = value(*b);
    };
    if (k == "uniform") {
      f.allowOnly({"distribution", "low", "high"}, "a uniform distribution");
      d.first = value(f.require("low"));
      d.second = value(f.require("high"));
    } else if (k == "normal") {
      f.allowOnly({"distribution", "mean", "sd", "lower", "upper"}, "a normal distribution");
      d.kind = StudyDistribution::Kind::normal;
      d.first = value(f.require("mean"));
      d.second = value(f.require("sd"));
    } else {
      f.allowOnly({"distribution", "median", "sigma", "lower", "upper"},
                  "a lognormal distribution");
      d.kind = StudyDistribution::Kind::lognormal;
      d.first = value(f.require("median"));
      d.second = f.require("sigma").number(s.c.evaluator, dim::none);
    }
    bound("lower", d.lower);
    bound("upper", d.upper);
    requireSensible(d, [&](const std::string& why) { f.fail(why); });
    p.distribution = d;
    return p;
  }
  f.allowOnly({"values", "from", "to", "steps"}, "a study parameter");
  if (auto values = f.get("values")) {
    if (f.has("from") || f.has("to") || f.has("steps"))
      values->fail("give either values or from/to/steps, not both");
    for (const Field& v : values->items()) p.values.push_back(value(v));
    if (p.values.empty()) values->fail("the list of values is empty");
    if (int(p.values.size()) > kMaxSweepValues)
      values->fail("at most " + std::to_string(kMaxSweepValues) + " values");
    return p;
  }
  const double a = value(f.require("from"));
  const double b = value(f.require("to"));
  const int n = f.require("steps").integer(s.c.evaluator, 1, kMaxSweepValues - 1);
  for (int i = 0; i < n; ++i) p.values.push_back(a + (b - a) * i / n);
  p.values.push_back(b);
  return p;
}

/// The deck's `study:` block into spec.
void readStudyBlock(const StudyContext& s, const Field& block, DesignStudySpec& spec) {
  block.allowOnly({"parameters", "sampling", "samples", "seed", "outputs"}, "the study");
  if (auto params = block.get("parameters")) {
    for (const auto& [name, f] : params->entries())
      spec.parameters.push_back(readParameter(s, name, f, spec.parameters));
    if (spec.parameters.empty()) params->fail("no parameters to vary");
  }
  if (auto sampling = block.get("sampling")) {
    const std::string name = sampling->choice(kSamplingNames);
    spec.sampling = StudySampling(
        std::find(kSamplingNames.begin(), kSamplingNames.end(), name) - kSamplingNames.begin());
  }
  if (auto samples = block.get("samples"))
    spec.samples = samples->integer(s.c.evaluator, 1, int(std::min<long long>(kMaxStudyPoints,
                                                                             2147483647LL)));
  if (auto seed = block.get("seed"))
    spec.seed = std::uint64_t(seed->integer(s.c.evaluator, 0, 2147483647));
  if (auto outputs = block.get("outputs")) {
    for (const Field& item : outputs->items()) {
      StudyOutput o;
      o.place = item.place();
      if (item.isMap()) {
        item.allowOnly({"quantity", "limit", "lower_limit"}, "a study output");
        const Field q = item.require("quantity");
        o.text = q.text();
        auto limit = item.get("limit");
        if (auto lower = item.get("lower_limit")) {
          if (limit) lower->fail("give one limit, limit (upper) or lower_limit, not both");
          limit = lower;
          o.lowerLimit = true;
        }
        if (limit) {
          try {
            o.limit = limit->number(s.c.evaluator, referenceUnit(parseQuantity(o.text)));
          } catch (const std::invalid_argument& e) {
            q.fail(e.what());
          }
        }
        resolveOutput(s, o, q);
      } else {
        o.text = item.text();
        resolveOutput(s, o, item);
      }
      spec.outputs.push_back(std::move(o));
    }
  }
}

/// Every check's quantity once, in deck order: the outputs of a study that names none.
std::vector<StudyOutput> checkOutputs(const StudyContext& s) {
  std::vector<StudyOutput> outputs;
  for (const DeckCheck& k : s.deck.checks) {
    const std::string text = k.quantity.text;
    const bool seen = std::any_of(outputs.begin(), outputs.end(), [&](const StudyOutput& o) {
      return o.text == text && o.analysis == k.analysis;
    });
    if (!seen) outputs.push_back({text, k.quantity, k.analysis, std::nullopt, k.place});
  }
  return outputs;
}

}  // namespace

DesignStudySpec readDesignStudy(const DeckSource& source, const Deck& deck,
                                const StudyCommandLine& commandLine) {
  const ClosedFormBudget budget;  // the closed forms' work, bounded per reading
  const StudyContext s(source, deck);
  DesignStudySpec spec;
  const Field root = Field::root(*source.tree);
  std::optional<Field> block = root.get("study");
  if (block && block->isNull()) block.reset();
  if (block) readStudyBlock(s, *block, spec);

  // The command line replaces the block's parts it gives.
  const DeckPlace commandPlace{0, 0, "beamrotor study"};
  if (!commandLine.sweeps.empty() || !commandLine.samples.empty()) {
    spec.parameters.clear();
    for (const std::string& text : commandLine.sweeps) {
      const DeckSweep sweep = parseSweepOption(text, deck);
      requireFreeParameter(deck, sweep.parameter, spec.parameters, [&](const std::string& why) {
        throw DeckError(deck.path, sweep.place, why);
      });
      spec.parameters.push_back({sweep.parameter, sweep.values, std::nullopt, sweep.place});
    }
    for (const std::string& text : commandLine.samples)
      spec.parameters.push_back(parseSampleOption(text, deck, spec.parameters));
    if (!commandLine.samples.empty() && spec.sampling == StudySampling::grid)
      spec.sampling = StudySampling::random;
  }
  if (!commandLine.sampling.empty()) {
    const auto it = std::find(kSamplingNames.begin(), kSamplingNames.end(), commandLine.sampling);
    if (it == kSamplingNames.end())
      throw DeckError(deck.path, DeckPlace{0, 0, "--sampling " + commandLine.sampling},
                      "expected one of: " + joinNames(kSamplingNames));
    spec.sampling = StudySampling(it - kSamplingNames.begin());
  }
  if (commandLine.count) {
    if (*commandLine.count < 1 || *commandLine.count > kMaxStudyPoints)
      throw DeckError(deck.path, DeckPlace{0, 0, "--samples " + std::to_string(*commandLine.count)},
                      "expected a whole number from 1 to " + std::to_string(kMaxStudyPoints));
    spec.samples = *commandLine.count;
  }
  if (commandLine.seed) spec.seed = *commandLine.seed;
  if (!commandLine.outputs.empty()) {
    spec.outputs.clear();
    for (const std::string& text : commandLine.outputs)
      spec.outputs.push_back(parseOutputOption(text, s));
  }

  // Without a study: the deck's sweep as a grid of one parameter.
  if (spec.parameters.empty() && deck.sweep)
    spec.parameters.push_back(
        {deck.sweep->parameter, deck.sweep->values, std::nullopt, deck.sweep->place});
  if (spec.parameters.empty())
    throw DeckError(deck.path, commandPlace,
                    "nothing to vary: give --sweep NAME=FROM:TO:STEPS, --sample "
                    "NAME=normal(MEAN,SD) or a study: block in the deck");
  if (spec.outputs.empty()) spec.outputs = checkOutputs(s);
  if (spec.outputs.empty())
    throw DeckError(deck.path, commandPlace,
                    "nothing to record: the deck has no checks; name outputs with --output "
                    "QUANTITY (e.g. --output 'stress max')");

  // Grid or sampling: every parameter must fit the one chosen.
  const bool sampled = spec.sampling != StudySampling::grid;
  for (const StudyParameter& p : spec.parameters) {
    if (sampled && !p.distribution)
      throw DeckError(deck.path, p.place,
                      "'" + p.name + "' has grid values, but the study samples (" +
                          kSamplingNames[int(spec.sampling)] +
                          "): give it a distribution, or sample nothing");
    if (!sampled && p.distribution)
      throw DeckError(deck.path, p.place,
                      "'" + p.name + "' has a distribution, but the study is a grid: choose "
                      "sampling: random or latin-hypercube");
  }
  if (sampled && spec.samples < 1)
    throw DeckError(deck.path, block ? block->place() : commandPlace,
                    "a sampled study needs its number of points: samples: N (or --samples N)");
  if (!sampled && spec.points() > kMaxStudyPoints)
    throw DeckError(deck.path, spec.parameters.back().place,
                    "the grid has more than " + std::to_string(kMaxStudyPoints) + " points");
  return spec;
}

}  // namespace beamrotor

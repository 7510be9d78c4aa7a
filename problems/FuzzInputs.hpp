// What the fuzz targets do with one input (problems/fuzz_deck.cpp, problems/fuzz_options.cpp),
// in one place so that `make test` replays every kept finding through the same code
// (tests/problems/test_fuzz_inputs.cpp). Each function answers bad input with the reader's
// own errors, which it swallows; any other exception, crash, hang or sanitizer report is a bug.
#pragma once

#include <sstream>
#include <string>
#include <vector>

#include "problems/deck/parse/DeckError.hpp"
#include "problems/deck/DeckReader.hpp"
#include "problems/deck/parse/Expression.hpp"
#include "problems/deck/structure/FormulationOption.hpp"
#include "problems/deck/study/DesignStudy.hpp"
#include "problems/deck/study/Overrides.hpp"
#include "problems/deck/Quantity.hpp"
#include "problems/deck/study/SweepOption.hpp"
#include "problems/run/ModelBuilder.hpp"

namespace beamrotor::fuzz {

/// Models above this many elements are read but not built: building is linear in the element
/// count and the fuzzer's time is better spent on more inputs.
inline constexpr double kLargestBuilt = 2000;

inline void buildIfSmall(const Deck& deck) {
  double elements = double(deck.points.size());
  for (const DeckSegment& s : deck.segments) elements += s.elementEstimate();
  if (elements <= kLargestBuilt) buildModel(deck);
}

/// Arbitrary bytes read as a deck and, when small, built into a model; then its design study
/// (its `study:` block, or its sweep as a grid) read as `beamrotor study` reads it.
inline void deckInput(const std::string& text) {
  try {
    const DeckSource source = parseDeckText(text, "fuzz.yaml");
    const Deck deck = readDeck(source);
    buildIfSmall(deck);
    readDesignStudy(source, deck, {});
  } catch (const DeckError&) {
    // The reader's own answer to bad input: expected.
  }
}

/// The deck the command-line values are tried against: parameters of every kind of use (a
/// length, a load, a position, a count).
inline constexpr const char* kOptionsDeck = R"(parameters: {L: 1.2, P: 1000, a: 0.6, n: 4, D: 0.05}
derived: {EI: 200e9 * pi * D^4 / 64}
materials: [{name: steel, E: 200e9, nu: 0.3, rho: 7850}]
sections: [{name: rod, shape: circle, D: D}]
segments: [{name: beam, length: L, section: rod, elements: n}]
points: [{name: load, at: a}]
supports: [{name: root, at: start, fix: clamped}]
loads: [{type: point, at: load, fy: -P}]
analyses: [{type: static, name: bend}, {type: modal, name: vib, modes: 2}]
checks: [{name: tip, quantity: displacement end uy, reference: -P*a^2*(3*L-a)/(6*EI), tolerance: 1e-6}]
)";

/// A `beamrotor study` option ('m' --sample NAME=DIST(...), 3 samples; 'g' a grid's --sweep;
/// 'o' --output QUANTITY [<=|>= LIMIT]) read against `deck`: only DeckError may answer it
/// (an ExpressionError escaping the study reader once became exit 1, "cannot write").
inline void studyOptionInput(char kind, const std::string& value, const DeckSource& source,
                             const Deck& deck) {
  StudyCommandLine study;
  if (kind == 'm') {
    study.samples = {value};
    study.count = 3;
  } else if (kind == 'g') {
    study.sweeps = {value};
  } else {
    study.sweeps = {"P=1,2"};
    study.outputs = {value};
  }
  try {
    readDesignStudy(source, deck, study);
  } catch (const DeckError&) {
  }
}

/// Lines of command-line values, each kind by its first byte: 's' --set NAME=VALUE (then the
/// deck re-read with it), 'w' --sweep SPEC (then the deck re-read at its first values), 'e' an
/// expression of the deck's names (evaluated, and compiled as a function of t), 'f'
/// --formulation, 'q' a check quantity; and `beamrotor study`'s: 'm' --sample
/// NAME=DIST(...) (3 samples), 'g' a grid's --sweep, 'o' --output QUANTITY [<=|>= LIMIT].
inline void optionsInput(const std::string& text) {
  const DeckSource source = parseDeckText(kOptionsDeck, "options.yaml");
  const Deck deck = readDeck(source);
  std::istringstream lines(text);
  for (std::string line; std::getline(lines, line);) {
    if (line.empty()) continue;
    const std::string value = line.substr(1);
    if (line[0] == 'm' || line[0] == 'g' || line[0] == 'o') {
      studyOptionInput(line[0], value, source, deck);
      continue;
    }
    try {
      switch (line[0]) {
        case 's':
          buildIfSmall(readDeck(source, {parseOverride(value, source.path)}));
          break;
        case 'w': {
          const DeckSweep sweep = parseSweepOption(value, deck);
          for (std::size_t i = 0; i < sweep.values.size() && i < 3; ++i)
            buildIfSmall(readDeck(source, {{sweep.parameter, sweep.values[i], "sweep"}}));
          break;
        }
        case 'e': {
          ExpressionEvaluator evaluator;
          for (const auto& [name, v] : deck.parameters) evaluator.define(name, v);
          evaluator.evaluate(value);
          const CompiledExpression f = evaluator.compile(value, {"t"});
          for (double t : {0.0, 1.0, -1.0, 1e300}) f(t);
          break;
        }
        case 'f': {
          Deck copy = deck;
          applyFormulationOption(value, copy);
          buildIfSmall(copy);
          break;
        }
        case 'q':
          parseQuantity(value);
          break;

        default:
          break;
      }
    } catch (const DeckError&) {
    } catch (const ExpressionError&) {
    } catch (const std::invalid_argument&) {  // parseQuantity's answer
    }
  }
}

}  // namespace beamrotor::fuzz

// Command-line overrides of deck parameters: "--set NAME=VALUE".
#pragma once

#include <string>
#include <vector>

namespace beamrotor {

/// A parameter value that replaces the deck's own.
struct ParameterOverride {
  std::string name;
  double value = 0;
  std::string text;  ///< as typed, e.g. "eta=0.2", for messages
};

/// Parses "NAME=VALUE"; VALUE is a number or an expression of constants ("1e-3", "0.4/2").
/// Throws DeckError naming `deckPath` and the argument.
ParameterOverride parseOverride(const std::string& argument, const std::string& deckPath);

/// The override for `name`, or nullptr. When a name is set twice the last one wins.
const ParameterOverride* findOverride(const std::vector<ParameterOverride>& overrides,
                                      const std::string& name);

}  // namespace beamrotor

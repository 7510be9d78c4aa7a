// Command-line overrides of deck parameters: "--set NAME=VALUE", the value with or without a
// unit ("--set L=6000mm").
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "problems/deck/parse/Units.hpp"

namespace beamrotor {

/// A parameter value that replaces the deck's own.
struct ParameterOverride {
  std::string name;
  double value = 0;
  std::string text;  ///< as typed, e.g. "eta=0.2", for messages
  /// The dimension of a value typed with a unit (value is then in SI units); nullopt for a
  /// bare number, which takes the deck parameter's own dimension.
  std::optional<Dimension> dimension = std::nullopt;
};

/// Parses "NAME=VALUE"; VALUE is a number or an expression of constants and units ("1e-3",
/// "0.4/2", "6000 mm").
/// Throws DeckError naming `deckPath` and the argument.
ParameterOverride parseOverride(const std::string& argument, const std::string& deckPath);

/// Why a value of dimension `given`, typed on the command line for parameter `name`, cannot
/// replace the deck's value of dimension `expected`; nullopt when it can (same dimension).
std::optional<std::string> overrideMismatch(const std::string& name, const Dimension& given,
                                            const Dimension& expected);

/// The override for `name`, or nullptr. When a name is set twice the last one wins.
const ParameterOverride* findOverride(const std::vector<ParameterOverride>& overrides,
                                      const std::string& name);

}  // namespace beamrotor

// Arithmetic in decks: any numeric field may be a muparser expression of the deck's parameters
// ("0.715 - eta", "P*L^3/(3*E*I)"). Names are defined one by one, so a parameter can use the
// ones before it; values are constants to the parser, so an expression cannot assign.
#pragma once

#include <memory>
#include <stdexcept>
#include <string>
#include <vector>

namespace mu {
class Parser;
}

namespace beamrotor {

/// An expression that does not parse or whose value is not a finite number. The message says
/// why, without the deck location (the caller adds it).
class ExpressionError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

class ExpressionEvaluator {
 public:
  /// Knows the constant pi, muparser's functions (sin, sqrt, abs, min, max, ...) and the
  /// deck functions of ExpressionFunctions.hpp (crank_position, ...).
  ExpressionEvaluator();
  ~ExpressionEvaluator();
  ExpressionEvaluator(const ExpressionEvaluator&) = delete;
  ExpressionEvaluator& operator=(const ExpressionEvaluator&) = delete;

  /// Makes `name` = value available to later expressions. Throws ExpressionError when the name
  /// is not an identifier, is reserved (a function or built-in constant) or already defined.
  void define(const std::string& name, double value);
  /// Whether `name` was defined with define().
  bool defines(const std::string& name) const;
  /// The names defined so far, in order.
  const std::vector<std::string>& names() const { return names_; }

  /// The value of `text` (a single expression). Throws ExpressionError when it does not parse
  /// or evaluates to inf or nan.
  double evaluate(const std::string& text) const;

  /// Letters, digits and '_', starting with a letter.
  static bool isIdentifier(const std::string& name);

 private:
  std::unique_ptr<mu::Parser> parser_;
  std::vector<std::string> names_;
};

}  // namespace beamrotor

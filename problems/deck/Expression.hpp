// Arithmetic in decks: any numeric field may be a muparser expression of the deck's parameters
// ("0.715 - eta", "P*L^3/(3*E*I)"). Names are defined one by one, so a parameter can use the
// ones before it; values are constants to the parser, so an expression cannot assign.
#pragma once

#include <memory>
#include <stdexcept>
#include <string>
#include <unordered_set>
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

class CompiledExpression;

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

  /// `text` as a function of `variables` (e.g. {"t"}), with the names defined so far as
  /// constants: parsed once, then evaluated from muparser's byte code at every call. Throws
  /// ExpressionError when it does not parse, names an unknown name, or is not finite with every
  /// variable 0.
  CompiledExpression compile(const std::string& text,
                             const std::vector<std::string>& variables) const;

  /// Letters, digits and '_', starting with a letter.
  static bool isIdentifier(const std::string& name);

 private:
  std::unique_ptr<mu::Parser> parser_;
  std::vector<std::string> names_;
  std::unordered_set<std::string> defined_;  // names_, for lookups in constant time
};

/// An expression of a few variables, compiled (see ExpressionEvaluator::compile). Copies share
/// one parser, so a copy is cheap; calls are not thread-safe.
class CompiledExpression {
 public:
  /// The value for `values` (one per variable, in compile order). Throws ExpressionError
  /// when it is not finite.
  double operator()(const std::vector<double>& values) const;
  /// The value of a function of one variable.
  double operator()(double x) const;
  const std::string& text() const;

 private:
  friend class ExpressionEvaluator;
  double evaluate() const;
  struct State;
  std::shared_ptr<State> state_;
};

}  // namespace beamrotor

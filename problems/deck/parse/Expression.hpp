// Arithmetic in decks: any numeric field may be a muparser expression of the deck's parameters
// ("0.715 - eta", "P*L^3/(3*E*I)"), with units ("12 kN/m", "q*L^2/8" with L: 6 m). Names are
// defined one by one, so a parameter can use the ones before it; values are constants to the
// parser, so an expression cannot assign.
//
// Dimensions are tracked by evaluating each expression again in scaled base units: with the
// metre made 2 times larger every length-valued constant doubles, so an expression's value
// scales as 2^e where e is its length exponent; likewise for mass, time, angle and temperature. A
// last evaluation with all five bases scaled at once must agree with the exponents found, else the
// expression adds, subtracts or compares different dimensions (or passes a quantity with a
// unit to a function that needs a plain number). Scaling by powers of two is exact in floating
// point, so a consistent expression gives exact exponents. Trigonometric functions take either
// a plain number (radians) or an angle (`sin(30 deg)`): both readings are tried.
#pragma once

#include <memory>
#include <stdexcept>
#include <string>
#include <unordered_map>
#include <vector>

#include "problems/deck/parse/Units.hpp"

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
class ExpressionMemo;

/// A value with its dimension: `si` in SI units (m, kg, s, rad and their products).
struct Amount {
  double si = 0;
  Dimension dimension;
  /// An exact zero has no dimension that evaluation can see (0 m = 0 kg): it fits any field.
  bool anyDimension = false;
};

class ExpressionEvaluator {
 public:
  /// Knows the constant pi, muparser's functions (sin, sqrt, abs, min, max, ...) and the
  /// deck functions of ExpressionFunctions.hpp (crank_position, ...).
  ExpressionEvaluator();
  /// The same, remembering in `memo` what it evaluates and taking from it what an earlier
  /// evaluator sharing the memo already evaluated (see ExpressionMemo); null: no memo. The
  /// memo must outlive the evaluator.
  explicit ExpressionEvaluator(ExpressionMemo* memo);
  ~ExpressionEvaluator();
  ExpressionEvaluator(const ExpressionEvaluator&) = delete;
  ExpressionEvaluator& operator=(const ExpressionEvaluator&) = delete;

  /// Makes `name` = value available to later expressions. Throws ExpressionError when the name
  /// is not an identifier, is reserved (a function or built-in constant) or already defined.
  /// A plain (dimensionless) number.
  void define(const std::string& name, double value);
  /// A value with a unit (`L: 6 m`). A name may hide a unit of the same name (a parameter `m`);
  /// the unit is then not available after a number in later expressions.
  void define(const std::string& name, const Amount& value);
  /// The dimension of a name defined with define(); none for an unknown one.
  Dimension dimensionOf(const std::string& name) const;
  /// Whether `name` was defined with define().
  bool defines(const std::string& name) const;
  /// The names defined so far, in order, and their values.
  const std::vector<std::string>& names() const { return names_; }
  const std::vector<Amount>& values() const { return values_; }

  /// The value of `text` (a single expression) and its dimension. Throws ExpressionError when
  /// it does not parse, evaluates to inf or nan, or mixes dimensions.
  Amount amount(const std::string& text) const;
  /// amount(text).si: the SI value, whatever its dimension.
  double evaluate(const std::string& text) const;

  /// `text` as a function of `variables` (e.g. {"t"}), with the names defined so far and the
  /// units (in SI, except those named like a variable) as constants: parsed once, then evaluated
  /// from muparser's byte code at every call. Throws ExpressionError when it does not parse, names
  /// an unknown name, or is not finite with every variable 0.
  CompiledExpression compile(const std::string& text,
                             const std::vector<std::string>& variables) const;

  /// Letters, digits and '_', starting with a letter.
  static bool isIdentifier(const std::string& name);

 private:
  /// The value of `text` in each scaled system of units (see above), unit products inserted.
  std::vector<double> valuesInEveryScaling(const std::string& text) const;
  void defineConstant(const std::string& name, const Amount& value);
  /// Creates the parsers (with the names defined so far) if a memo left them out until now.
  void requireParsers() const;
  /// amount() computed in full, then remembered in memo_ when there is one.
  Amount amountInFull(const std::string& text) const;
  /// amount() from the values in every scaling.
  Amount amountInEveryScaling(const std::string& text) const;

  mutable std::vector<std::unique_ptr<mu::Parser>> parsers_;  // one per scaling; [0] is SI
  std::vector<std::string> names_;
  std::vector<Amount> values_;                          // of names_, for requireParsers()
  std::unordered_map<std::string, Dimension> defined_;  // names_, for lookups in constant time
  ExpressionMemo* memo_ = nullptr;
};

/// What evaluators reading the same deck again and again (a design study: the deck at every
/// point) share: each expression they met, keyed by its text and the number of names defined
/// before it, compiled once into byte code that reads every name as a variable, with the
/// dimension its first evaluation found. A later evaluator then evaluates the byte code once
/// (in SI) instead of parsing the text in nine systems of units. Its value is bit for bit the
/// one the full evaluation gives: there every name is a constant and muparser folds the whole
/// expression as it parses, operation by operation in evaluation order; the memo's byte code,
/// its optimiser off (which would reorder products of variables and constants), performs the
/// same operations in the same order. Dimensions depend only on
/// the names' dimensions, which do not change between readings; a zero value fits any
/// dimension, as in the full evaluation (where a consistent expression that is zero in SI is
/// zero in every system: scaling by powers of two is exact). Evaluated in full: values that
/// are not finite, a value other than zero of an expression whose dimension is not yet known
/// (every earlier value zero), names defined in another order, and texts not met before. Not
/// thread-safe: one per thread.
class ExpressionMemo {
 public:
  ExpressionMemo();
  ~ExpressionMemo();
  ExpressionMemo(const ExpressionMemo&) = delete;
  ExpressionMemo& operator=(const ExpressionMemo&) = delete;
  /// Expressions evaluated in full, and from byte code, so far.
  long long fullEvaluations() const { return full_; }
  long long memoEvaluations() const { return memo_; }

 private:
  friend class ExpressionEvaluator;
  struct Entry;
  struct State;
  std::unique_ptr<State> state_;
  long long full_ = 0, memo_ = 0;
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

#include "problems/deck/Expression.hpp"

#include <muParser.h>

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstdio>
#include <numbers>

#include "problems/deck/ExpressionFunctions.hpp"
#include "problems/deck/Suggest.hpp"

namespace beamrotor {

namespace {

/// Longest expression accepted: far beyond any closed form, short enough to bound parse time.
constexpr std::size_t kLongestExpression = 4096;

std::string shortNumber(double v) {
  if (std::isnan(v)) return "nan";
  char buf[32];
  std::snprintf(buf, sizeof buf, "%g", v);
  return buf;
}

}  // namespace

ExpressionEvaluator::ExpressionEvaluator() : parser_(std::make_unique<mu::Parser>()) {
  parser_->DefineConst("pi", std::numbers::pi);
  defineDeckFunctions(*parser_);
}

ExpressionEvaluator::~ExpressionEvaluator() = default;

bool ExpressionEvaluator::isIdentifier(const std::string& name) {
  if (name.empty() || name.size() > 64 || !std::isalpha(static_cast<unsigned char>(name[0])))
    return false;
  return std::all_of(name.begin(), name.end(), [](char c) {
    return std::isalnum(static_cast<unsigned char>(c)) || c == '_';
  });
}

bool ExpressionEvaluator::defines(const std::string& name) const {
  return std::find(names_.begin(), names_.end(), name) != names_.end();
}

void ExpressionEvaluator::define(const std::string& name, double value) {
  if (!isIdentifier(name))
    throw ExpressionError("'" + name +
                          "' is not a valid name (letters, digits and '_', starting with a "
                          "letter, at most 64 characters)");
  if (name == "pi" || parser_->GetFunDef().count(name))
    throw ExpressionError("'" + name + "' is reserved (a built-in function or constant)");
  if (defines(name)) throw ExpressionError("'" + name + "' is defined twice");
  if (!std::isfinite(value)) throw ExpressionError("'" + name + "' is not finite");
  parser_->DefineConst(name, value);
  names_.push_back(name);
}

double ExpressionEvaluator::evaluate(const std::string& text) const {
  if (text.size() > kLongestExpression)
    throw ExpressionError("expression longer than " + std::to_string(kLongestExpression) +
                          " characters");
  if (text.find_first_not_of(" \t") == std::string::npos)
    throw ExpressionError("empty value; expected a number or an expression");
  int count = 0;
  double value = 0;
  try {
    parser_->SetExpr(text);
    const double* results = parser_->Eval(count);
    if (count != 1)
      throw ExpressionError("'" + text + "' gives " + std::to_string(count) +
                            " comma-separated values; expected one number");
    value = results[0];
  } catch (const mu::Parser::exception_type& e) {
    std::string why = e.GetMsg();
    // An unknown name is the commonest mistake: say so, and suggest a defined one.
    if (e.GetCode() == mu::ecUNASSIGNABLE_TOKEN && isIdentifier(e.GetToken())) {
      std::vector<std::string> known = names_;
      known.push_back("pi");
      why = "unknown name '" + e.GetToken() + "'" + didYouMean(e.GetToken(), known) +
            " (defined so far: " + joinNames(names_) + ")";
    }
    throw ExpressionError("cannot evaluate '" + text + "': " + why);
  }
  if (!std::isfinite(value))
    throw ExpressionError("'" + text + "' evaluates to " + shortNumber(value) +
                          " (division by zero or a function outside its domain?)");
  return value;
}

}  // namespace beamrotor

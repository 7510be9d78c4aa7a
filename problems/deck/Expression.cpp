#include "problems/deck/Expression.hpp"

#include <muParser.h>

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstdio>
#include <numbers>

#include "problems/deck/ExpressionFunctions.hpp"
#include "problems/deck/SceneFunctions.hpp"
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

/// The reason a muparser error gives, with a did-you-mean for an unknown name among `known`.
std::string reason(const mu::Parser::exception_type& e, std::vector<std::string> known) {
  // An unknown name is the commonest mistake: say so, and suggest a defined one.
  if (e.GetCode() == mu::ecUNASSIGNABLE_TOKEN && ExpressionEvaluator::isIdentifier(e.GetToken())) {
    const std::string defined = known.empty() ? "" : " (defined so far: " + joinNames(known) + ")";
    known.push_back("pi");
    return "unknown name '" + e.GetToken() + "'" + didYouMean(e.GetToken(), known) +
           defined;
  }
  return e.GetMsg();
}

/// What every deck expression may use beyond muparser's own: pi and the scene functions.
void defineDeckBuiltins(mu::Parser& parser) {
  parser.DefineConst("pi", std::numbers::pi);
  defineSceneFunctions(parser);
  defineDeckFunctions(parser);
}

}  // namespace

ExpressionEvaluator::ExpressionEvaluator() : parser_(std::make_unique<mu::Parser>()) {
  defineDeckBuiltins(*parser_);
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
  return defined_.count(name) > 0;
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
  defined_.insert(name);
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
    throw ExpressionError("cannot evaluate '" + text + "': " + reason(e, names_));
  }
  if (!std::isfinite(value))
    throw ExpressionError("'" + text + "' evaluates to " + shortNumber(value) +
                          " (division by zero or a function outside its domain?)");
  return value;
}

struct CompiledExpression::State {
  mu::Parser parser;
  std::vector<double> variables;  // muparser reads them through pointers: never resized
  std::vector<std::string> names;
  std::string text;
};

CompiledExpression ExpressionEvaluator::compile(const std::string& text,
                                                const std::vector<std::string>& variables) const {
  if (text.size() > kLongestExpression)
    throw ExpressionError("expression longer than " + std::to_string(kLongestExpression) +
                          " characters");
  CompiledExpression out;
  out.state_ = std::make_shared<CompiledExpression::State>();
  auto& st = *out.state_;
  st.text = text;
  st.variables.assign(variables.size(), 0.0);
  st.names = variables;
  std::vector<std::string> known = names_;
  try {
    defineDeckBuiltins(st.parser);
    for (const auto& [name, value] : parser_->GetConst())
      if (name != "pi" && name != "_pi" && name != "_e") st.parser.DefineConst(name, value);
    for (std::size_t i = 0; i < variables.size(); ++i) {
      if (defines(variables[i]))
        throw ExpressionError("'" + variables[i] + "' is both a parameter and a variable here");
      st.parser.DefineVar(variables[i], &st.variables[i]);
      known.push_back(variables[i]);
    }
    st.parser.SetExpr(text);
    int count = 0;
    st.parser.Eval(count);
    if (count != 1)
      throw ExpressionError("'" + text + "' gives " + std::to_string(count) +
                            " comma-separated values; expected one number");
  } catch (const mu::Parser::exception_type& e) {
    throw ExpressionError("cannot evaluate '" + text + "': " + reason(e, known));
  }
  out(std::vector<double>(variables.size(), 0.0));  // finite where every variable is 0
  return out;
}

double CompiledExpression::operator()(const std::vector<double>& values) const {
  std::copy(values.begin(), values.end(), state_->variables.begin());
  return evaluate();
}

double CompiledExpression::operator()(double x) const {
  state_->variables.at(0) = x;  // no allocation: this runs once per time step
  return evaluate();
}

double CompiledExpression::evaluate() const {
  const std::vector<double>& values = state_->variables;
  double value = 0;
  try {
    value = state_->parser.Eval();
  } catch (const mu::Parser::exception_type& e) {
    throw ExpressionError("cannot evaluate '" + state_->text + "': " + e.GetMsg());
  }
  if (!std::isfinite(value)) {
    std::string at;
    for (std::size_t i = 0; i < values.size(); ++i)
      at += (i ? ", " : " at ") + state_->names[i] + " = " + shortNumber(values[i]);
    throw ExpressionError("'" + state_->text + "' evaluates to " + shortNumber(value) + at);
  }
  return value;
}

const std::string& CompiledExpression::text() const {
  return state_->text;
}

}  // namespace beamrotor

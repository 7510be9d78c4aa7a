#include "problems/deck/parse/Expression.hpp"

#include <muParser.h>

#include <algorithm>
#include <array>
#include <cctype>
#include <charconv>
#include <cmath>
#include <cstdio>
#include <deque>
#include <limits>
#include <numbers>
#include <optional>
#include <stdexcept>

#include "problems/deck/parse/ExpressionFunctions.hpp"
#include "problems/deck/parse/SceneFunctions.hpp"
#include "problems/deck/parse/Suggest.hpp"
#include "problems/deck/parse/UnitSyntax.hpp"

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

/// One system of units in which expressions are evaluated: base unit d is 2^exponent[d] times
/// its SI size. `angleArguments`: trigonometric functions read their argument as an angle in
/// this system (sin(30 deg)) rather than as a plain number of radians (sin(0.5)).
struct Scaling {
  std::array<int, Dimension::kBases> exponent;
  bool angleArguments;
};

// [0] SI; [1..3] length, mass, time doubled; [4], [5] angle doubled, read both ways; [6]
// temperature doubled; [7], [8] every base scaled at once (the check), angles read both ways.
constexpr std::array<Scaling, 9> kScalings{{{{0, 0, 0, 0, 0}, false},
                                            {{1, 0, 0, 0, 0}, false},
                                            {{0, 1, 0, 0, 0}, false},
                                            {{0, 0, 1, 0, 0}, false},
                                            {{0, 0, 0, 1, 0}, false},
                                            {{0, 0, 0, 1, 0}, true},
                                            {{0, 0, 0, 0, 1}, false},
                                            {{3, -5, 7, -2, 4}, false},
                                            {{3, -5, 7, -2, 4}, true}}};

/// The size in scaled system `s` of a value whose SI size is `si`.
double scaled(double si, const Dimension& d, const Scaling& s) {
  double e = 0;
  for (int i = 0; i < Dimension::kBases; ++i) e += d.exponents[i] * s.exponent[i];
  return si * std::exp2(e);
}

// Trigonometric functions whose angles are in a system where the radian is 2^E radians.
template <int E>
double sinIn(double x) {
  return std::sin(std::ldexp(x, -E));
}
template <int E>
double cosIn(double x) {
  return std::cos(std::ldexp(x, -E));
}
template <int E>
double tanIn(double x) {
  return std::tan(std::ldexp(x, -E));
}
template <int E>
double asinIn(double x) {
  return std::ldexp(std::asin(x), E);
}
template <int E>
double acosIn(double x) {
  return std::ldexp(std::acos(x), E);
}
template <int E>
double atanIn(double x) {
  return std::ldexp(std::atan(x), E);
}

template <int E>
void defineAngleFunctions(mu::Parser& parser) {
  parser.DefineFun("sin", sinIn<E>);
  parser.DefineFun("cos", cosIn<E>);
  parser.DefineFun("tan", tanIn<E>);
  parser.DefineFun("asin", asinIn<E>);
  parser.DefineFun("acos", acosIn<E>);
  parser.DefineFun("atan", atanIn<E>);
}

std::unique_ptr<mu::Parser> parserFor(const Scaling& s) {
  auto parser = std::make_unique<mu::Parser>();
  defineDeckBuiltins(*parser);
  if (s.angleArguments) {
    if (s.exponent[Dimension::kAngle] == 1) defineAngleFunctions<1>(*parser);
    if (s.exponent[Dimension::kAngle] == -2) defineAngleFunctions<-2>(*parser);
  }
  for (const Unit& u : units()) parser->DefineConst(u.name, scaled(u.si, u.dimension, s));
  return parser;
}

/// The exponent of one base from the value v0 in SI and v in the system where that base is
/// doubled; nullopt unless v / v0 is a power of 2 with an exponent in sixths.
std::optional<double> exponentFrom(double v0, double v) {
  if (!(v / v0 > 0)) return std::nullopt;
  const double e = std::log2(v / v0);
  const double sixths = std::round(6 * e);
  if (std::abs(6 * e - sixths) > 1e-9) return std::nullopt;
  return sixths / 6;
}

/// The dimension the values in every scaling show, reading angles in functions as plain
/// numbers (angleArguments false) or as angles; nullopt when they do not fit one dimension.
std::optional<Dimension> dimensionFrom(const std::vector<double>& v, bool angleArguments) {
  const int angle = angleArguments ? 5 : 4, check = angleArguments ? 8 : 7;
  Dimension d;
  const int from[Dimension::kBases] = {1, 2, 3, angle, 6};
  for (int i = 0; i < Dimension::kBases; ++i) {
    const auto e = exponentFrom(v[0], v[from[i]]);
    if (!e) return std::nullopt;
    d.exponents[i] = *e;
  }
  const double predicted = scaled(v[0], d, kScalings[check]);
  if (!(std::abs(v[check] - predicted) <= 1e-9 * std::abs(predicted))) return std::nullopt;
  return d;
}

/// The value of a plain decimal literal (an optional minus, digits, an optional fraction and
/// exponent: "-5000", "0.3", "2.1e11"), or nullopt for any other text or one that does not fit
/// a finite double. Such text means the same to muparser (a minus applied to the number it
/// reads with strtod, both correctly rounded) in every scaling, so it is dimensionless and
/// needs no parse: most numbers of a generated deck (coordinates, loads) are literals.
std::optional<double> plainNumber(const std::string& text) {
  const char* p = text.data();
  const char* const end = p + text.size();
  const auto digits = [&] {
    const char* from = p;
    while (p != end && *p >= '0' && *p <= '9') ++p;
    return p != from;
  };
  if (p != end && *p == '-') ++p;
  if (!digits()) return std::nullopt;
  if (p != end && *p == '.') {
    ++p;
    digits();
  }
  if (p != end && (*p == 'e' || *p == 'E')) {
    ++p;
    if (p != end && (*p == '+' || *p == '-')) ++p;
    if (!digits()) return std::nullopt;
  }
  if (p != end) return std::nullopt;
  double x = 0;
  const auto [last, error] = std::from_chars(text.data(), end, x);
  // Subnormal numbers go the full way too (a reader may flag their loss of precision).
  if (error != std::errc() || last != end || !std::isfinite(x) ||
      (x != 0 && std::abs(x) < std::numeric_limits<double>::min()))
    return std::nullopt;
  return x;
}

}  // namespace

ExpressionEvaluator::ExpressionEvaluator() : ExpressionEvaluator(nullptr) {}

ExpressionEvaluator::ExpressionEvaluator(ExpressionMemo* memo) : memo_(memo) {
  if (!memo_) requireParsers();
}

void ExpressionEvaluator::requireParsers() const {
  if (!parsers_.empty()) return;
  for (const Scaling& s : kScalings) parsers_.push_back(parserFor(s));
  for (std::size_t i = 0; i < names_.size(); ++i)
    for (std::size_t k = 0; k < parsers_.size(); ++k)
      parsers_[k]->DefineConst(names_[i], scaled(values_[i].si, values_[i].dimension, kScalings[k]));
}

/// One expression compiled for the memo: every name defined before it is a variable.
struct ExpressionMemo::Entry {
  std::size_t names = 0;  ///< how many names were defined when it was met
  std::unique_ptr<mu::Parser> parser;
  /// Found by a full evaluation at a value other than zero; unknown while every value was zero
  std::optional<Dimension> dimension;
};

struct ExpressionMemo::State {
  /// The current reading's values of the names, in definition order; muparser reads them
  /// through pointers, so they live in a deque (never moved).
  std::deque<double> values;
  std::vector<std::string> names;  ///< the names in definition order, as first met
  std::unordered_map<std::string, std::vector<Entry>> entries;
};

ExpressionMemo::ExpressionMemo() : state_(std::make_unique<State>()) {}
ExpressionMemo::~ExpressionMemo() = default;

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

Dimension ExpressionEvaluator::dimensionOf(const std::string& name) const {
  const auto found = defined_.find(name);
  return found == defined_.end() ? Dimension{} : found->second;
}

void ExpressionEvaluator::define(const std::string& name, double value) {
  define(name, Amount{value, Dimension{}, false});
}

void ExpressionEvaluator::define(const std::string& name, const Amount& value) {
  if (!isIdentifier(name))
    throw ExpressionError("'" + name +
                          "' is not a valid name (letters, digits and '_', starting with a "
                          "letter, at most 64 characters)");
  const std::size_t index = names_.size();
  if (memo_) {
    ExpressionMemo::State& m = *memo_->state_;
    // A name met at this place in an earlier reading passed the checks below there; any other
    // needs the parsers (and makes the memo's byte code, which reads names by place, useless).
    if (index >= m.names.size() || m.names[index] != name) {
      m.entries.clear();
      m.names.resize(index);
      m.names.push_back(name);
      requireParsers();
    }
  }
  if (!parsers_.empty() && (name == "pi" || parsers_[0]->GetFunDef().count(name)))
    throw ExpressionError("'" + name + "' is reserved (a built-in function or constant)");
  if (defines(name)) throw ExpressionError("'" + name + "' is defined twice");
  if (!std::isfinite(value.si)) throw ExpressionError("'" + name + "' is not finite");
  if (memo_) {
    std::deque<double>& values = memo_->state_->values;
    if (index >= values.size()) values.resize(index + 1);
    values[index] = value.si;
  }
  defineConstant(name, value);
  names_.push_back(name);
  values_.push_back(value);
  defined_.emplace(name, value.dimension);
}

void ExpressionEvaluator::defineConstant(const std::string& name, const Amount& value) {
  for (std::size_t i = 0; i < parsers_.size(); ++i)
    parsers_[i]->DefineConst(name, scaled(value.si, value.dimension, kScalings[i]));
}

std::vector<double> ExpressionEvaluator::valuesInEveryScaling(const std::string& text) const {
  requireParsers();
  if (text.size() > kLongestExpression)
    throw ExpressionError("expression longer than " + std::to_string(kLongestExpression) +
                          " characters");
  if (text.find_first_not_of(" \t") == std::string::npos)
    throw ExpressionError("empty value; expected a number or an expression");
  std::string written;
  try {
    written = writeUnitProducts(text, [this](const std::string& word) {
      return defines(word) || (parsers_[0]->GetConst().count(word) > 0 && !findUnit(word));
    });
  } catch (const std::invalid_argument& e) {
    throw ExpressionError("cannot evaluate '" + text + "': " + e.what());
  }
  std::vector<double> values;
  for (const auto& parser : parsers_) {
    int count = 0;
    try {
      parser->SetExpr(written);
      const double* results = parser->Eval(count);
      if (count != 1)
        throw ExpressionError("'" + text + "' gives " + std::to_string(count) +
                              " comma-separated values; expected one number");
      values.push_back(results[0]);
    } catch (const mu::Parser::exception_type& e) {
      throw ExpressionError("cannot evaluate '" + text + "': " + reason(e, names_));
    }
    if (values.size() == 1 && !std::isfinite(values[0]))
      throw ExpressionError("'" + text + "' evaluates to " + shortNumber(values[0]) +
                            " (division by zero or a function outside its domain?)");
  }
  return values;
}

Amount ExpressionEvaluator::amount(const std::string& text) const {
  // A literal: what the evaluation in every scaling gives (its zero fits any dimension).
  if (const std::optional<double> x =
          text.size() <= kLongestExpression ? plainNumber(text) : std::nullopt)
    return *x == 0 ? Amount{0, Dimension{}, true} : Amount{*x, Dimension{}, false};
  if (memo_) {
    ExpressionMemo::State& m = *memo_->state_;
    if (const auto found = m.entries.find(text); found != m.entries.end())
      for (const ExpressionMemo::Entry& e : found->second) {
        if (e.names != names_.size()) continue;
        double v = 0;
        try {
          v = e.parser->Eval();
        } catch (const mu::Parser::exception_type&) {
          break;  // said in full
        }
        if (!std::isfinite(v) || (v != 0 && !e.dimension)) break;  // said or found in full
        ++memo_->memo_;
        // Zero: the full evaluation's zero in every system of units (scaling by powers of two
        // is exact, so a consistent expression that is zero in SI is zero in all).
        if (v == 0) return Amount{0, Dimension{}, true};
        return Amount{v, *e.dimension, false};
      }
  }
  return amountInFull(text);
}

Amount ExpressionEvaluator::amountInFull(const std::string& text) const {
  const Amount a = amountInEveryScaling(text);
  if (!memo_) return a;
  ++memo_->full_;
  ExpressionMemo::State& m = *memo_->state_;
  std::vector<ExpressionMemo::Entry>& entries = m.entries[text];
  for (ExpressionMemo::Entry& e : entries)
    if (e.names == names_.size()) {  // remembered, its dimension unknown until now
      if (!a.anyDimension) e.dimension = a.dimension;
      return a;
    }
  ExpressionMemo::Entry e;
  e.names = names_.size();
  if (!a.anyDimension) e.dimension = a.dimension;
  e.parser = std::make_unique<mu::Parser>();
  mu::Parser& p = *e.parser;
  p.EnableOptimizer(false);
  defineDeckBuiltins(p);
  for (const auto& [name, value] : parsers_[0]->GetConst())
    if (name != "pi" && name != "_pi" && name != "_e" && !defines(name))
      p.DefineConst(name, value);
  try {
    for (std::size_t i = 0; i < names_.size(); ++i) p.DefineVar(names_[i], &m.values[i]);
    p.SetExpr(writeUnitProducts(text, [this](const std::string& word) {
      return defines(word) || (parsers_[0]->GetConst().count(word) > 0 && !findUnit(word));
    }));
  } catch (const mu::Parser::exception_type&) {
    return a;
  }
  // The first evaluation parses; a byte code that disagrees with the full evaluation is never
  // kept (it cannot, by the argument in the header, but a wrong memo would be silent).
  try {
    if (p.Eval() == a.si) entries.push_back(std::move(e));
  } catch (const mu::Parser::exception_type&) {
    // not remembered: evaluated in full every time
  }
  return a;
}

Amount ExpressionEvaluator::amountInEveryScaling(const std::string& text) const {
  const std::vector<double> v = valuesInEveryScaling(text);
  if (!std::all_of(v.begin(), v.end(), [](double x) { return std::isfinite(x); }))
    throw ExpressionError("'" + text +
                          "' is too close to the largest number a double holds for its "
                          "dimension to be checked");
  if (v[0] == 0) {
    if (std::all_of(v.begin(), v.end(), [](double x) { return x == 0; }))
      return Amount{0, Dimension{}, true};
  } else if (auto d = dimensionFrom(v, false)) {
    return Amount{v[0], *d, false};
  } else if (auto angled = dimensionFrom(v, true)) {
    return Amount{v[0], *angled, false};
  }
  throw ExpressionError(
      "'" + text +
      "' mixes dimensions: it adds, subtracts or compares quantities of different "
      "dimensions, or gives a quantity with a unit to a function that needs a plain number "
      "(divide it by its unit first, e.g. exp(x/m))");
}

double ExpressionEvaluator::evaluate(const std::string& text) const {
  return amount(text).si;
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
  requireParsers();
  CompiledExpression out;
  out.state_ = std::make_shared<CompiledExpression::State>();
  auto& st = *out.state_;
  st.text = text;
  st.variables.assign(variables.size(), 0.0);
  st.names = variables;
  std::vector<std::string> known = names_;
  try {
    defineDeckBuiltins(st.parser);
    const auto isVariable = [&](const std::string& name) {
      return std::find(variables.begin(), variables.end(), name) != variables.end();
    };
    for (const auto& [name, value] : parsers_[0]->GetConst())
      if (name != "pi" && name != "_pi" && name != "_e" && !(findUnit(name) && isVariable(name)))
        st.parser.DefineConst(name, value);
    for (std::size_t i = 0; i < variables.size(); ++i) {
      if (defines(variables[i]))
        throw ExpressionError("'" + variables[i] + "' is both a parameter and a variable here");
      st.parser.DefineVar(variables[i], &st.variables[i]);
      known.push_back(variables[i]);
    }
    st.parser.SetExpr(writeUnitProducts(
        text, [&](const std::string& word) { return defines(word) || isVariable(word); }));
    int count = 0;
    st.parser.Eval(count);
    if (count != 1)
      throw ExpressionError("'" + text + "' gives " + std::to_string(count) +
                            " comma-separated values; expected one number");
  } catch (const mu::Parser::exception_type& e) {
    throw ExpressionError("cannot evaluate '" + text + "': " + reason(e, known));
  } catch (const std::invalid_argument& e) {
    throw ExpressionError("cannot evaluate '" + text + "': " + e.what());
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

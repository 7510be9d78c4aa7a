#include "problems/deck/Field.hpp"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstdio>
#include <set>
#include <string_view>

#include "problems/deck/Expression.hpp"
#include "problems/deck/PlainText.hpp"
#include "problems/deck/Suggest.hpp"

namespace beamrotor {

namespace {

/// Scalars are quoted in messages but cut short: a message stays one readable line.
std::string quoted(const std::string& text) {
  constexpr std::size_t kShown = 60;
  std::string shown = text.size() > kShown ? text.substr(0, kShown) + "..." : text;
  return "'" + shown + "'";
}

}  // namespace

std::string formatNumber(double v) {
  if (std::isnan(v)) return "nan";
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.6g", v);
  return buf;
}

Field::Field(YAML::Node node, std::string path, std::shared_ptr<const std::string> file,
             DeckPlace fallback)
    : node_(std::move(node)),
      path_(std::move(path)),
      file_(std::move(file)),
      fallback_(std::move(fallback)) {}

Field Field::root(const YAML::Node& node, const std::string& file) {
  return Field(node, "", std::make_shared<const std::string>(file), placeOf(node.Mark()));
}

Field Field::child(const YAML::Node& node, const std::string& path, const YAML::Node& key) const {
  // A null value's mark points past it (often to the next line), and an alias's mark to its
  // anchor: the key is the better place for both.
  DeckPlace fallback = key.IsDefined() ? placeOf(key.Mark()) : place();
  return Field(node, path, file_, fallback);
}

DeckPlace Field::place() const {
  DeckPlace p = fallback_;
  if (!isNull()) {
    const DeckPlace own = placeOf(node_.Mark());
    if (own.line > 0 && (p.line == 0 || own.line >= p.line)) p = own;
  }
  p.field = path_;
  return p;
}

void Field::fail(const std::string& message) const {
  throw DeckError(*file_, place(), message);
}

std::string Field::describe() const {
  if (isNull()) return "nothing";
  if (isMap()) return "a map";
  if (isList()) return "a list";
  return "the value " + quoted(node_.Scalar());
}

std::vector<std::pair<std::string, Field>> Field::entries() const {
  if (!isMap()) fail("expected a map (key: value lines), got " + describe());
  std::vector<std::pair<std::string, Field>> out;
  std::set<std::string> seen;
  for (const auto& entry : node_) {
    const YAML::Node key = entry.first;
    const std::string keyPath = path_.empty() ? "" : path_ + ".";
    if (!key.IsScalar()) {
      Field(key, path_, file_, placeOf(key.Mark())).fail("a key must be a plain word");
    }
    const std::string name = key.Scalar();
    Field value = child(entry.second, keyPath + name, key);
    if (!seen.insert(name).second)
      value.fail("duplicate key '" + name + "' (it appears earlier in the same map)");
    out.emplace_back(name, std::move(value));
  }
  return out;
}

void Field::allowOnly(const std::vector<std::string>& allowed, const std::string& what) const {
  for (const auto& [key, value] : entries()) {
    bool known = false;
    for (const std::string& a : allowed) known = known || a == key;
    if (known) continue;
    DeckPlace at = value.fallback_;  // the key itself
    at.field = value.path_;
    throw DeckError(*file_, at,
                    "unknown key in " + what + didYouMean(key, allowed) +
                        " (allowed: " + joinNames(allowed) + ")");
  }
}

std::optional<Field> Field::get(const std::string& key) const {
  // entries() without building a Field for every entry (a design study reads its deck at
  // every point): the keys are checked as entries() checks them, and on the first problem
  // entries() itself fails with its message.
  if (!isMap()) entries();
  std::vector<std::string_view> seen;  // the keys' text lives in the tree
  std::optional<Field> found;
  for (const auto& entry : node_) {
    const YAML::Node name = entry.first;
    if (!name.IsScalar() ||
        std::find(seen.begin(), seen.end(), std::string_view(name.Scalar())) != seen.end())
      entries();
    seen.emplace_back(name.Scalar());
    if (!found && name.Scalar() == key)
      found = child(entry.second, path_.empty() ? key : path_ + "." + key, name);
  }
  return found;
}

Field Field::require(const std::string& key) const {
  std::optional<Field> value = get(key);
  if (!value) {
    DeckPlace at = place();
    at.field = path_.empty() ? key : path_ + "." + key;
    throw DeckError(*file_, at, "missing required field '" + key + "'");
  }
  if (value->isNull()) value->fail("no value given");
  return *value;
}

std::vector<Field> Field::items() const {
  if (!isList()) fail("expected a list ('- item' lines or [a, b]), got " + describe());
  std::vector<Field> out;
  int index = 0;
  for (const YAML::Node& item : node_) {
    out.push_back(Field(item, path_ + "[" + std::to_string(index) + "]", file_, place()));
    ++index;
  }
  return out;
}

std::vector<Field> Field::itemsOrSingle() const {
  if (isList()) return items();
  return {*this};
}

std::string Field::text() const {
  if (!isScalar()) fail("expected a single value, got " + describe());
  return node_.Scalar();
}

std::string Field::label(std::size_t longest) const {
  const std::string s = text();
  if (s.empty() || s.size() > longest)
    fail("expected 1 to " + std::to_string(longest) + " characters, got " +
         std::to_string(s.size()));
  if (const auto bad = firstNonPlain(s))
    fail("holds " + describeNonPlain(s, *bad) + " at character " + std::to_string(*bad + 1) +
         "; text here must be one line of printable UTF-8");
  return s;
}

std::string Field::name() const {
  const std::string s = text();
  const bool ok = !s.empty() && s.size() <= 64 && std::all_of(s.begin(), s.end(), [](char c) {
    return std::isalnum(static_cast<unsigned char>(c)) || c == '_' || c == '-' || c == '.';
  });
  if (!ok)
    fail("expected a name (letters, digits, '_', '-', '.'; at most 64 characters), got " +
         quoted(s));
  return s;
}

Amount Field::amount(const ExpressionEvaluator& evaluator) const {
  if (!isScalar()) fail("expected a number or an expression, got " + describe());
  try {
    return evaluator.amount(node_.Scalar());
  } catch (const ExpressionError& e) {
    fail(e.what());
  }
}

double Field::number(const ExpressionEvaluator& evaluator) const {
  return number(evaluator, fieldUnitAt(path_));
}

double Field::number(const ExpressionEvaluator& evaluator, const FieldUnit& unit) const {
  const Amount a = amount(evaluator);
  if (a.anyDimension || a.dimension.dimensionless()) return a.si;  // bare: in the field's unit
  if (a.dimension != unit.dimension) {
    const std::size_t dot = path_.find_last_of('.');
    const std::string key = dot == std::string::npos ? path_ : path_.substr(dot + 1);
    fail(key + " expects " + describeDimension(unit.dimension) + ", got " +
         describeDimension(a.dimension));
  }
  return a.si / unit.bareSize;
}

double Field::positive(const ExpressionEvaluator& evaluator) const {
  return positive(evaluator, fieldUnitAt(path_));
}

double Field::positive(const ExpressionEvaluator& evaluator, const FieldUnit& unit) const {
  const double v = number(evaluator, unit);
  if (!(v > 0)) fail("must be positive, got " + formatNumber(v));
  return v;
}

double Field::nonNegative(const ExpressionEvaluator& evaluator) const {
  return nonNegative(evaluator, fieldUnitAt(path_));
}

double Field::nonNegative(const ExpressionEvaluator& evaluator, const FieldUnit& unit) const {
  const double v = number(evaluator, unit);
  if (!(v >= 0)) fail("must not be negative, got " + formatNumber(v));
  return v;
}

int Field::integer(const ExpressionEvaluator& evaluator, int lowest, int highest) const {
  const double v = number(evaluator);
  if (v != std::round(v)) fail("must be a whole number, got " + formatNumber(v));
  if (v < lowest || v > highest)
    fail("must lie between " + std::to_string(lowest) + " and " + std::to_string(highest) +
         ", got " + formatNumber(v));
  return int(v);
}

bool Field::boolean() const {
  const std::string s = text();
  for (const char* t : {"true", "True", "TRUE", "yes", "Yes", "on", "On"})
    if (s == t) return true;
  for (const char* f : {"false", "False", "FALSE", "no", "No", "off", "Off"})
    if (s == f) return false;
  fail("expected true or false, got " + quoted(s));
}

std::string Field::choice(const std::vector<std::string>& choices) const {
  const std::string s = text();
  for (const std::string& c : choices)
    if (s == c) return s;
  fail("unknown value " + quoted(s) + didYouMean(s, choices) +
       " (expected one of: " + joinNames(choices) + ")");
}

}  // namespace beamrotor

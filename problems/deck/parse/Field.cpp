#include "problems/deck/parse/Field.hpp"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstdio>
#include <set>

#include "problems/deck/parse/Expression.hpp"
#include "problems/deck/parse/NumericReads.hpp"
#include "problems/deck/parse/PlainText.hpp"
#include "problems/deck/parse/Suggest.hpp"

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

namespace {

DeckPlace placeOfNode(const DeckNode& node) {
  return {node.line, node.column, ""};
}

}  // namespace

Field::Field(const DeckNode* node, std::string path, const std::string* file, DeckPlace fallback)
    : node_(node), path_(std::move(path)), file_(file), fallback_(std::move(fallback)) {}

Field Field::root(const DeckTree& tree) {
  return Field(&tree.root(), "", &tree.file(), placeOfNode(tree.root()));
}

Field Field::child(const DeckNode& node, const std::string& path, const DeckNode& key) const {
  // A null value's mark points past it (often to the next line), and an alias's mark to its
  // anchor: the key is the better place for both.
  return Field(&node, path, file_, placeOfNode(key));
}

DeckPlace Field::place() const {
  DeckPlace p = fallback_;
  if (!isNull()) {
    const DeckPlace own = placeOfNode(*node_);
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
  return "the value " + quoted(node_->text);
}

std::vector<std::pair<std::string, Field>> Field::entries() const {
  if (!isMap()) fail("expected a map (key: value lines), got " + describe());
  std::vector<std::pair<std::string, Field>> out;
  std::set<std::string> seen;
  const std::string keyPath = path_.empty() ? "" : path_ + ".";
  for (const auto& [key, value] : node_->entries) {
    if (key->kind != DeckNode::Kind::scalar)
      Field(key, path_, file_, placeOfNode(*key)).fail("a key must be a plain word");
    const std::string& name = key->text;
    Field field = child(*value, keyPath + name, *key);
    if (!seen.insert(name).second)
      field.fail("duplicate key '" + name + "' (it appears earlier in the same map)");
    out.emplace_back(name, std::move(field));
  }
  return out;
}

void Field::requireMapKeys() const {
  // The tree marked each map whose keys pass entries()'s checks; entries() fails on the others.
  if (!isMap() || !node_->plainUniqueKeys) entries();
}

void Field::allowOnly(const std::vector<std::string>& allowed, const std::string& what) const {
  requireMapKeys();
  if (NumericReadLog* log = NumericReadLog::open()) log->recordAllowed({path_, allowed});
  for (const auto& [key, value] : node_->entries) {
    bool known = false;
    for (const std::string& a : allowed) known = known || a == key->text;
    if (known) continue;
    DeckPlace at = placeOfNode(*key);
    at.field = path_.empty() ? key->text : path_ + "." + key->text;
    throw DeckError(*file_, at,
                    "unknown key in " + what + didYouMean(key->text, allowed) +
                        " (allowed: " + joinNames(allowed) + ")");
  }
}

std::optional<Field> Field::get(const std::string& key) const {
  requireMapKeys();
  for (const auto& [name, value] : node_->entries)
    if (name->text == key) return child(*value, path_.empty() ? key : path_ + "." + key, *name);
  return std::nullopt;
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
  out.reserve(node_->items.size());
  const DeckPlace here = place();
  int index = 0;
  for (const DeckNode* item : node_->items) {
    out.push_back(Field(item, path_ + "[" + std::to_string(index) + "]", file_, here));
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
  if (NumericReadLog* log = NumericReadLog::open()) log->recordText(path_);
  return node_->text;
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
    return evaluator.amount(node_->text);
  } catch (const ExpressionError& e) {
    fail(e.what());
  }
}

double Field::number(const ExpressionEvaluator& evaluator, const FieldUnit& unit) const {
  const Amount a = amount(evaluator);
  const bool bare = a.anyDimension || a.dimension.dimensionless();
  const double value = bare ? a.si : a.si / unit.bareSize;  // bare: in the field's unit
  if (!bare && a.dimension != unit.dimension) {
    const std::size_t dot = path_.find_last_of('.');
    const std::string key = dot == std::string::npos ? path_ : path_.substr(dot + 1);
    fail((key.empty() ? std::string("the value") : key) + " expects " +
         describeDimension(unit.dimension) + ", got " + describeDimension(a.dimension));
  }
  if (NumericReadLog* log = NumericReadLog::open())
    log->record({*file_, place(), node_->text, unit, value, bare});
  return value;
}

double Field::positive(const ExpressionEvaluator& evaluator, const FieldUnit& unit) const {
  const double v = number(evaluator, unit);
  if (!(v > 0)) fail("must be positive, got " + formatNumber(v));
  return v;
}

double Field::nonNegative(const ExpressionEvaluator& evaluator, const FieldUnit& unit) const {
  const double v = number(evaluator, unit);
  if (!(v >= 0)) fail("must not be negative, got " + formatNumber(v));
  return v;
}

int Field::integer(const ExpressionEvaluator& evaluator, int lowest, int highest) const {
  const double v = number(evaluator, dim::none);
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

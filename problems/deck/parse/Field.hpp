// Typed, located reads from a deck's tree (DeckTree.hpp). A Field is one node plus its dotted
// path ("segments[1].length") and file, so every failed read becomes a DeckError that names the
// file, line, column and field. A Field points into its tree, which must outlive it.
#pragma once

#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "problems/deck/parse/DeckError.hpp"
#include "problems/deck/parse/DeckTree.hpp"
#include "problems/deck/parse/Units.hpp"

namespace beamrotor {

class ExpressionEvaluator;
struct Amount;

class Field {
 public:
  /// The top-level node of a deck's tree.
  static Field root(const DeckTree& tree);

  /// Dotted path of this field, e.g. "supports[0].prescribe.uy"; empty at the top.
  const std::string& path() const { return path_; }
  /// Line and column (1-based) and path, for messages.
  DeckPlace place() const;
  const std::string& file() const { return *file_; }
  /// Throws DeckError at this field.
  [[noreturn]] void fail(const std::string& message) const;

  bool isMap() const { return node_->kind == DeckNode::Kind::map; }
  bool isList() const { return node_->kind == DeckNode::Kind::list; }
  bool isScalar() const { return node_->kind == DeckNode::Kind::scalar; }
  bool isNull() const { return node_->kind == DeckNode::Kind::null; }
  /// "a map", "a list", "the value 'x'" or "nothing", for messages.
  std::string describe() const;

  // --- maps ---------------------------------------------------------------------------------
  /// The entries of a map in file order; fails when this is not a map, a key is not a plain
  /// word or a key appears twice.
  std::vector<std::pair<std::string, Field>> entries() const;
  /// Fails (with a did-you-mean suggestion) on any key not in `allowed`; fails when this is
  /// not a map. `what` names the map in the message, e.g. "a segment".
  void allowOnly(const std::vector<std::string>& allowed, const std::string& what) const;
  /// The value under `key` (possibly null, as in `length:` with nothing after it), or nullopt
  /// when the key is absent. Fails when this is not a map.
  std::optional<Field> get(const std::string& key) const;
  /// The value under `key`; fails "missing required field" when absent, "no value" when null.
  Field require(const std::string& key) const;
  bool has(const std::string& key) const { return get(key).has_value(); }

  // --- lists --------------------------------------------------------------------------------
  /// The items of a list ("name[0]", "name[1]", ...); fails when this is not a list.
  std::vector<Field> items() const;
  /// The items of a list, or this single value as a one-item list.
  std::vector<Field> itemsOrSingle() const;

  // --- scalars ------------------------------------------------------------------------------
  /// The scalar's text; fails when this is a map, list or null.
  std::string text() const;
  /// Free text shown to people (a title, a check's name, a unit): 1 to `longest` bytes of
  /// valid UTF-8 without control characters (a line break would end the line it is written on
  /// in a chart script or table).
  std::string label(std::size_t longest) const;
  /// A name (letters, digits, '_', '-', '.'), as used for points, sections, supports.
  std::string name() const;
  /// The value of a number or expression, with or without a unit, in the field's bare unit
  /// `unit`, which every read states (dim::none for a ratio or a count). A value without a
  /// unit (dimensionless) is taken in the bare unit; one with a unit must have the field's
  /// dimension. Fails with the evaluator's reason, or "E expects a pressure or stress (Pa), got
  /// a length (m)".
  double number(const ExpressionEvaluator& evaluator, const FieldUnit& unit) const;
  /// The value of a number or expression of any dimension (a parameter's).
  Amount amount(const ExpressionEvaluator& evaluator) const;
  /// number() that must be > 0.
  double positive(const ExpressionEvaluator& evaluator, const FieldUnit& unit) const;
  /// number() that must be >= 0.
  double nonNegative(const ExpressionEvaluator& evaluator, const FieldUnit& unit) const;
  /// A dimensionless number() that must be a whole number in [lowest, highest]: a count.
  int integer(const ExpressionEvaluator& evaluator, int lowest, int highest) const;
  /// true/false (also yes/no, on/off).
  bool boolean() const;
  /// One of `choices`; fails listing them (with a did-you-mean suggestion).
  std::string choice(const std::vector<std::string>& choices) const;

 private:
  Field(const DeckNode* node, std::string path, const std::string* file, DeckPlace fallback);
  Field child(const DeckNode& node, const std::string& path, const DeckNode& key) const;
  /// Fails as entries() does when this is not a map, a key is not a plain word or a key
  /// appears twice; builds no Field unless it fails.
  void requireMapKeys() const;

  const DeckNode* node_;
  std::string path_;
  const std::string* file_;  ///< the tree's
  DeckPlace fallback_;  // the key's place: used when the value has no useful mark of its own
};

/// "1.5", "2e+11": a number in messages.
std::string formatNumber(double v);

}  // namespace beamrotor

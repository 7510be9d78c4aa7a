#include "problems/deck/BareParameters.hpp"

#include <algorithm>
#include <cctype>
#include <memory>

#include "problems/deck/parse/Expression.hpp"

namespace beamrotor {

namespace {

/// The identifiers in an expression (not the exponent letters of numbers such as 1e5).
std::vector<std::string> identifiers(const std::string& text) {
  std::vector<std::string> out;
  const auto word = [](char c) { return std::isalnum(static_cast<unsigned char>(c)) || c == '_'; };
  for (std::size_t i = 0; i < text.size();) {
    const bool starts = std::isalpha(static_cast<unsigned char>(text[i])) &&
                        (i == 0 || (!word(text[i - 1]) && text[i - 1] != '.'));
    if (!starts) {
      ++i;
      continue;
    }
    std::size_t j = i;
    while (j < text.size() && word(text[j])) ++j;
    out.push_back(text.substr(i, j - i));
    i = j;
  }
  return out;
}

Dimension divided(const Dimension& d, double p) {
  Dimension out = d;
  for (double& e : out.exponents) e /= p;
  return out;
}

class Inference {
 public:
  Inference(const ExpressionEvaluator& ev, const std::vector<std::string>& parameters,
            const std::vector<std::pair<std::string, std::string>>& texts)
      : ev_(ev), parameters_(parameters), texts_(texts.begin(), texts.end()) {}

  /// A value of `text` read into `dimension` (a field's), passed on through the named values
  /// it holds alone down to a parameter.
  void flow(std::string text, Dimension d, const BareUse& where) {
    int indirect = 0;
    for (std::size_t guard = 0; guard <= texts_.size(); ++guard) {  // names refer to earlier ones
      const std::string name = soleBareName(text);
      if (name.empty()) return;
      if (text != name) {
        // A plain number of an expression (`eta == 0.4`, a buckling factor's `Pe / P`) says
        // nothing: its bare numbers may carry any unit.
        if (d.dimensionless()) return;
        const Power p = power(text, name);
        if (p.independent) return;
        d = divided(d, p.mixed ? 1 : p.exponent);
        ++indirect;
      }
      if (std::find(parameters_.begin(), parameters_.end(), name) != parameters_.end())
        record(name, BareUse{d, where.file, where.place, where.bareSize}, indirect);
      const auto own = texts_.find(name);
      if (own == texts_.end()) return;
      text = own->second;
      indirect += 2;  // a named value in between: less direct than any expression in a field
    }
  }

  std::map<std::string, BareUse> found;

 private:
  /// A use `indirect` steps away: 0 where the field is the name itself, 1 for an expression
  /// of it, 2 more for each named value in between. The most direct uses decide: a bare
  /// number in an expression may carry a unit (`mass: Q / 9.80665` with Q a weight), so a
  /// less direct use that disagrees says nothing.
  void record(const std::string& name, const BareUse& use, int indirect) {
    const auto [it, added] = found.emplace(name, use);
    int& known = indirectness_[name];
    if (added || indirect < known) {
      it->second = use;
      known = indirect;
      return;
    }
    if (indirect > known || it->second.dimension == use.dimension) return;
    throw DeckError(use.file, use.place,
                    "parameter '" + name + "' has no unit and is used as " +
                        describeDimension(it->second.dimension) + " at " +
                        describeUse(it->second) + " and as " +
                        describeDimension(use.dimension) + " at " + describeUse(use) +
                        ": write it with its unit, or use it in one dimension");
  }

  bool isBare(const std::string& name) const {
    return ev_.defines(name) && ev_.dimensionOf(name).dimensionless();
  }

  /// The one bare name `text` holds, or "" when it holds none or several.
  std::string soleBareName(const std::string& text) const {
    std::string sole;
    for (const std::string& w : identifiers(text)) {
      if (!isBare(w) || w == sole) continue;
      if (!sole.empty()) return "";
      sole = w;
    }
    return sole;
  }

  /// How `text` holds `name`.
  struct Power {
    double exponent = 1;       ///< 1 for `L/2`, 2 for `d^2`, 0.5 for `sqrt(A)`
    bool mixed = false;        ///< a sum with bare numbers (`0.715 - eta`): they take its dimension
    bool independent = false;  ///< its dimension does not follow the name's (`E > 1e16 ? 1 : 2`)
  };

  /// Found by giving `name` a unit of length in an evaluator of its own.
  Power power(const std::string& text, const std::string& name) {
    auto& probe = probes_[name];
    if (!probe) {
      probe = std::make_unique<ExpressionEvaluator>();
      for (std::size_t i = 0; i < ev_.names().size(); ++i) {
        Amount v = ev_.values()[i];
        if (ev_.names()[i] == name) v = Amount{v.si == 0 ? 1 : v.si, dim::length, false};
        probe->define(ev_.names()[i], v);
      }
    }
    try {
      const Amount a = probe->amount(text);
      const double p = a.dimension.exponents[Dimension::kLength];
      if (a.anyDimension || p == 0) return Power{0, false, true};
      return Power{p, false, false};
    } catch (const ExpressionError&) {
      return Power{1, true, false};
    }
  }

  const ExpressionEvaluator& ev_;
  const std::vector<std::string>& parameters_;
  std::map<std::string, std::string> texts_;
  std::map<std::string, std::unique_ptr<ExpressionEvaluator>> probes_;
  std::map<std::string, int> indirectness_;  ///< of each found use
};

}  // namespace

std::string describeUse(const BareUse& use) {
  return use.file + ":" + std::to_string(use.place.line) + " (" + use.place.field + ")";
}

std::map<std::string, BareUse> bareDimensions(
    const std::vector<NumericRead>& reads, const ExpressionEvaluator& evaluator,
    const std::vector<std::string>& parameters,
    const std::vector<std::pair<std::string, std::string>>& texts) {
  Inference inference(evaluator, parameters, texts);
  for (const NumericRead& r : reads)
    if (r.bare)
      inference.flow(r.text, r.unit.dimension,
                     BareUse{r.unit.dimension, r.file, r.place, r.unit.bareSize});
  return inference.found;
}

}  // namespace beamrotor

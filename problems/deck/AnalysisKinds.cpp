#include "problems/deck/AnalysisKinds.hpp"

#include <stdexcept>
#include <utility>

#include "problems/deck/ReaderContext.hpp"

namespace beamrotor {

namespace {

/// Calls `f` with a default-constructed row of each alternative in turn, until it returns true.
template <class F, std::size_t... I>
bool anyRow(F&& f, std::index_sequence<I...>) {
  return (f(std::variant_alternative_t<I, AnalysisSpec>{}) || ...);
}

template <class F>
bool anyRow(F&& f) {
  return anyRow(std::forward<F>(f), std::make_index_sequence<std::variant_size_v<AnalysisSpec>>{});
}

template <class Spec>
concept HasModelFree = requires(const Field& f) {
  Spec::modelFree(f);
};

}  // namespace

std::vector<std::string> analysisTypeNames() {
  std::vector<std::string> names;
  anyRow([&](auto row) {
    names.emplace_back(decltype(row)::deckType);
    return false;
  });
  return names;
}

std::optional<AnalysisSpec> analysisSpecNamed(std::string_view type) {
  std::optional<AnalysisSpec> found;
  anyRow([&](auto row) {
    if (decltype(row)::deckType != type) return false;
    found = row;
    return true;
  });
  return found;
}

std::string analysisTypeName(const AnalysisSpec& spec) {
  return std::visit([](auto row) { return std::string(decltype(row)::deckType); }, spec);
}

bool answers(const AnalysisSpec& spec, const Quantity& q) {
  return std::visit([&](auto row) { return answers<decltype(row)>(q); }, spec);
}

std::string defaultAnalysisType(const Quantity& q) {
  std::string type;
  anyRow([&](auto row) {
    if (!answers<decltype(row)>(q)) return false;
    type = decltype(row)::deckType;
    return true;
  });
  // Every quantity the grammar accepts has a row (tests/problems/test_analysis_kinds.cpp).
  if (type.empty()) throw std::logic_error("no analysis kind answers '" + q.text + "'");
  return type;
}

bool isRotorAnalysis(const AnalysisSpec& spec) {
  return rotorSettings(spec) != nullptr;
}

const RotorFamily* rotorSettings(const AnalysisSpec& spec) {
  return std::visit(
      [](const auto& row) -> const RotorFamily* {
        if constexpr (std::is_base_of_v<RotorFamily, std::decay_t<decltype(row)>>)
          return &row;
        else
          return nullptr;
      },
      spec);
}

RotorFamily* rotorSettings(AnalysisSpec& spec) {
  return const_cast<RotorFamily*>(rotorSettings(std::as_const(spec)));
}

int modesComputed(const AnalysisSpec& spec) {
  return std::visit(
      [](const auto& row) {
        if constexpr (requires { row.modes; })
          return row.modes;
        else
          return 0;
      },
      spec);
}

namespace reader {

AnalysisSpec analysisKind(const Field& type) {
  return *analysisSpecNamed(type.choice(analysisTypeNames()));
}

void readAnalysisKind(const Context& c, const Field& f, DeckAnalysis& a) {
  std::visit(
      [&](auto& row) {
        row.read(c, f);
        if constexpr (std::decay_t<decltype(row)>::needsMass) requireMass(c, f, a.type());
      },
      a.kind);
  // Which members are slack depends on the loads: only a plain static solve finds them.
  const StaticSpec* statics = std::get_if<StaticSpec>(&a.kind);
  if (c.deck.frame && c.deck.frame->hasOneWayMembers() && (!statics || statics->secondOrder))
    f.fail("a deck with tension-only or compression-only members (acts:) solves linear static "
           "analyses only: which members are slack depends on the loads, found by the "
           "statics' active set; remove acts: or this analysis");
}

bool isMechanismAnalysis(const Field& analysis) {
  if (!analysis.isMap() || !analysis.has("type")) return false;
  const std::optional<AnalysisSpec> spec = analysisSpecNamed(analysis.require("type").text());
  return spec && std::visit(
                     [&](auto row) {
                       if constexpr (HasModelFree<decltype(row)>)
                         return decltype(row)::modelFree(analysis);
                       else
                         return false;
                     },
                     *spec);
}

}  // namespace reader

}  // namespace beamrotor

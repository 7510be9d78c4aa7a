#include "problems/deck/OutputChoices.hpp"

#include <array>

namespace beamrotor {

namespace {

constexpr std::array<std::pair<ChartFormat, std::string_view>, 4> kNames{
    {{ChartFormat::png, "png"},
     {ChartFormat::svg, "svg"},
     {ChartFormat::both, "both"},
     {ChartFormat::none, "none"}}};

}  // namespace

std::string_view chartFormatName(ChartFormat format) {
  for (const auto& [f, name] : kNames)
    if (f == format) return name;
  return "png";
}

std::optional<ChartFormat> chartFormatNamed(std::string_view name) {
  for (const auto& [f, named] : kNames)
    if (named == name) return f;
  return std::nullopt;
}

const std::vector<std::string>& chartFormatNames() {
  static const std::vector<std::string> names = [] {
    std::vector<std::string> list;
    for (const auto& [f, name] : kNames) list.emplace_back(name);
    return list;
  }();
  return names;
}

OutputChoices chooseOutput(const DeckOutput& deck, const DeckOutput& commandLine) {
  OutputChoices chosen;
  for (const DeckOutput* source : {&deck, &commandLine}) {
    if (source->charts) chosen.charts = *source->charts;
    if (source->pointFiles) chosen.pointFiles = *source->pointFiles;
    if (source->fullTables) chosen.fullTables = *source->fullTables;
    chosen.units = chosen.units.overlaid(source->units);
    if (source->allCases) chosen.allCases = *source->allCases;
  }
  return chosen;
}

}  // namespace beamrotor

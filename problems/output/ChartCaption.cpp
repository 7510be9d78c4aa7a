#include "problems/output/ChartCaption.hpp"

#include <algorithm>
#include <vector>

#include "problems/output/files/ChartParts.hpp"

namespace beamrotor {

std::string chartCaption(const RunResult& run, const std::string& analysis,
                         const std::string& what, const std::string& left,
                         const OutputUnits& units) {
  constexpr std::size_t kLine = 90;  // characters across a 900-pixel chart at its title font
  std::string text = run.deckName.empty() ? "" : run.deckName + ": ";
  text += analysis;
  text += what;
  std::vector<std::string> shown;
  const auto valueOf = [&](const std::string& name) -> const double* {
    for (const auto* list : {&run.parameters, &run.reported})
      for (const auto& [named, value] : *list)
        if (named == name) return &value;
    return nullptr;
  };
  std::vector<std::string> names = run.setParameters;
  for (const auto& [name, value] : run.reported) names.push_back(name);
  std::string line;
  for (const std::string& name : names) {
    const double* value = valueOf(name);
    if (!value || name == left || std::count(shown.begin(), shown.end(), name) > 0) continue;
    shown.push_back(name);
    OutputUnits::Shown shown{1, ""};
    for (const auto& [named, unit] : run.units)
      if (named == name && !unit.empty()) shown = units.valueIn(unit, {1, unit});
    std::string item = name;
    item += " = ";
    item += labelNumber(*value * shown.factor);
    if (!shown.unit.empty()) item += " " + shown.unit;
    if (!line.empty() && line.size() + 2 + item.size() > kLine) {
      text += "\n" + line;
      line.clear();
    }
    line += line.empty() ? item : ", " + item;
  }
  return line.empty() ? text : text + "\n" + line;
}

}  // namespace beamrotor

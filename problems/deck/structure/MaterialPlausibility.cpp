#include "problems/deck/structure/MaterialPlausibility.hpp"

#include <cmath>
#include <utility>

#include "problems/deck/parse/DeckError.hpp"

namespace beamrotor {

namespace {

/// " did you mean 210 GPa? ..." when the value in a larger unit of the same dimension would be
/// plausible; empty otherwise.
std::string unitHint(const PlausibleRange& r, double value) {
  const bool density = std::string(r.key) == "rho";
  // the units moduli and densities are given in (bar is for pressures of fluids)
  const std::vector<std::pair<std::string, double>> candidates =
      density ? std::vector<std::pair<std::string, double>>{{"t/m^3", 1e3}}
              : std::vector<std::pair<std::string, double>>{{"MPa", 1e6}, {"GPa", 1e9}};
  std::vector<std::string> fitting;
  for (const auto& [unit, size] : candidates) {
    const double scaled = value * size;
    if (scaled >= r.lowest && scaled <= r.highest) fitting.push_back(formatNumber(value) + " " + unit);
  }
  if (fitting.empty()) return "";
  std::string meant = fitting.front();
  for (std::size_t i = 1; i < fitting.size(); ++i) meant += " or " + fitting[i];
  return "; did you mean " + meant + "? write the unit, e.g. `" + r.key + ": " + fitting.back() +
         "`";
}

std::string unitOf(const PlausibleRange& r) {
  return std::string(r.key) == "rho" ? "kg/m^3" : "Pa";
}

}  // namespace

const std::vector<PlausibleRange>& plausibleMaterialRanges() {
  static const std::vector<PlausibleRange> ranges{
      {"E", 1e6, 1.2e12, "soft elastomers", "diamond"},
      {"G", 3e5, 6e11, "soft elastomers", "diamond"},
      {"rho", 10, 25000, "aerogels", "osmium"},
  };
  return ranges;
}

std::vector<std::string> materialWarnings(const Field& block,
                                          const std::vector<Material>& materials) {
  std::vector<std::string> out;
  const std::vector<Field> items = block.items();
  for (std::size_t i = 0; i < items.size() && i < materials.size(); ++i) {
    const Material& m = materials[i];
    auto warn = [&](const std::string& key, const std::string& message) {
      const Field at = items[i].get(key).value_or(items[i]);
      out.push_back(formatDeckMessage(at.file(), at.place(), message));
    };
    for (const PlausibleRange& r : plausibleMaterialRanges()) {
      const std::string key = r.key;
      if (!items[i].has(key)) continue;
      const double v = key == "E" ? m.E : key == "G" ? m.G : m.rho;
      if (key == "rho" && v == 0) continue;
      const std::string value = formatNumber(v) + " " + unitOf(r);
      if (v < r.lowest)
        warn(key, value + " is below every engineering material (" + formatNumber(r.lowest) +
                      " " + unitOf(r) + ", " + r.lowestExample + ")" + unitHint(r, v));
      else if (v > r.highest)
        warn(key, value + " is above every engineering material (" + formatNumber(r.highest) +
                      " " + unitOf(r) + ", " + r.highestExample + ")");
    }
    if (m.nu < 0)
      warn(items[i].has("nu") ? "nu" : "G",
           "Poisson's ratio " + formatNumber(m.nu) +
               " is negative: only auxetic foams and lattices expand sideways under tension");
  }
  return out;
}

}  // namespace beamrotor

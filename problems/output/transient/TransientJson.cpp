#include "problems/output/transient/TransientJson.hpp"

#include <algorithm>
#include <cmath>
#include <vector>

#include "problems/output/files/FileNames.hpp"

namespace beamrotor {

namespace {

Json historiesJson(const TransientOutcome& t, const std::vector<HistoryExtremes>& extremes) {
  Json out = Json::object();
  for (std::size_t k = 0; k < t.histories.size(); ++k) {
    const NamedHistory& h = t.histories[k];
    const auto largest = std::max_element(h.values.begin(), h.values.end(), [](double a, double b) {
      return std::abs(a) < std::abs(b);
    });
    const double time = largest == h.values.end()
                            ? 0.0
                            : t.result.times.at(std::size_t(largest - h.values.begin()));
    out[h.name] = {{"unit", h.unit},
                   {"max", extremes[k].max},
                   {"min", extremes[k].min},
                   {"max_abs", extremes[k].maxAbs},
                   {"time_of_max_abs", time},
                   {"final", h.values.empty() ? 0.0 : h.values.back()}};
  }
  return out;
}

/// Largest drift of kinetic + strain + damping - external from its start, relative to the
/// largest energy seen: round-off for Newmark without stops (see EnergyHistory); impacts on
/// stops with e < 1 dissipate energy the account does not book, so it shows here.
double energyBalanceError(const EnergyHistory& e) {
  if (e.kinetic.empty()) return 0;
  double scale = 0, drift = 0;
  for (std::size_t i = 0; i < e.kinetic.size(); ++i) {
    scale =
        std::max({scale, std::abs(e.kinetic[i]), std::abs(e.strain[i]), std::abs(e.external[i])});
    drift = std::max(drift, std::abs(e.balance(i) - e.balance(0)));
  }
  return scale > 0 ? drift / scale : 0.0;
}

}  // namespace

Json transientJson(const AnalysisOutcome& a) {
  const TransientOutcome& t = *resultOf<TransientOutcome>(a);
  const TransientResult& r = t.result;
  const std::string stem = fileStem(a.name);
  Json out = {{"type", a.type}, {"name", a.name}};
  out["scheme"] = r.scheme;
  out["dt"] = r.timeStep;
  out["steps"] = r.steps;
  out["end_time"] = r.steps * r.timeStep;
  out["factorizations"] = r.factorizations;
  std::vector<HistoryExtremes> extremes;  // each history's, taken once for both tables
  for (const NamedHistory& h : t.histories) extremes.push_back(h.extremes());
  Json maxima = Json::object();
  for (std::size_t k = 0; k < t.histories.size(); ++k)
    maxima[t.histories[k].name + "_max"] = extremes[k].maxAbs;
  out["maxima"] = maxima;
  out["histories"] = historiesJson(t, extremes);
  if (r.stability.omegaMax > 0)
    out["stability"] = {{"omega_max", r.stability.omegaMax},
                        {"dt_critical", r.stability.dtCritical},
                        {"dt_critical_safe", r.stability.dtCriticalSafe},
                        {"method", r.stability.method}};
  out["energy_balance_error"] = energyBalanceError(r.energy);
  Json impacts = Json::array();
  for (const Impact& i : r.impacts)
    impacts.push_back({{"time", i.time},
                       {"stop", i.stop},
                       {"velocity_before", i.velocityBefore},
                       {"velocity_after", i.velocityAfter}});
  out["impacts"] = impacts;
  out["warnings"] = r.warnings;
  out["time_s"] = r.time.total;
  Json files = {{"history_csv", historyCsv(stem)}};
  if (!r.frames.empty()) {
    Json vtus = Json::array();
    for (std::size_t i = 0; i < r.frames.size(); ++i) vtus.push_back(frameVtu(stem, int(i) + 1));
    files["pvd"] = collectionPvd(stem);
    files["vtu"] = vtus;
  }
  out["files"] = files;
  return out;
}

}  // namespace beamrotor

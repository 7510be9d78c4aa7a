// The envelope over the load combinations (see CaseEnvelope.hpp).
#include "problems/output/structure/CaseEnvelope.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace beamrotor {

namespace {

/// Keeps the larger (or smaller) of v and the bound's, with the combination that gave it; the
/// first of equal values governs.
void widen(Governed& bound, double v, int by, bool larger) {
  if (bound.by < 0 || (larger ? v > bound.value : v < bound.value)) bound = {v, by};
}

void widen(GovernedRange& range, double max, double min, int by) {
  widen(range.max, max, by, true);
  widen(range.min, min, by, false);
}

/// Widens each of `forces` (one combination's, in the order of every combination's list) by
/// that combination, k.
void widen(std::vector<std::pair<ReactionComponent, GovernedRange>>& envelope,
           const std::vector<ReactionComponent>& forces, int k) {
  if (envelope.empty())
    for (const ReactionComponent& r : forces) envelope.push_back({r, {}});
  for (std::size_t i = 0; i < forces.size() && i < envelope.size(); ++i)
    widen(envelope[i].second, forces[i].value, forces[i].value, k);
}

}  // namespace

CaseEnvelope caseEnvelope(const Model& model, const std::vector<CaseOutcome>& cases,
                          const std::vector<StaticExtremes>& extremes,
                          const std::vector<bool>& canGovern) {
  if (extremes.size() != cases.size() || canGovern.size() != cases.size())
    throw std::invalid_argument("caseEnvelope needs the extremes of every case");
  CaseEnvelope out;
  for (int k = 0; k < int(cases.size()); ++k) {
    const CaseOutcome& c = cases[k];
    if (!c.combination || !canGovern[std::size_t(k)]) continue;
    const StaticExtremes& x = extremes[k];
    widen(out.reactions, c.statics.reactions, k);
    widen(out.springs, c.statics.elementForces, k);
    out.members.resize(rangedMembers(x));
    for (std::size_t m = 0; m < out.members.size(); ++m)
      for (std::size_t f = 0; f < kForceComponents.size(); ++f) {
        const RangeValues r = rangeValuesOf(x, m, f);
        widen(out.members[m][f], r.max, r.min, k);
      }
    if (!model.members().empty()) widen(out.largestDisplacement, x.largestDisplacement.value, k, true);
    if (const auto top = largestPeak(x.peaks, &ElementPeaks::stress))
      widen(out.largestStress, top->value, k, true);
  }
  return out;
}

std::vector<int> governingCombinations(const CaseEnvelope& envelope, bool planar) {
  std::vector<int> out{envelope.largestDisplacement.by, envelope.largestStress.by};
  for (ForceComponent f : planar ? std::vector<ForceComponent>{ForceComponent::Mz}
                                 : std::vector<ForceComponent>{ForceComponent::Mz,
                                                               ForceComponent::My}) {
    Governed top, bottom;
    for (const auto& member : envelope.members) {
      const GovernedRange& r = member[int(f)];
      widen(top, r.max.value, r.max.by, true);
      widen(bottom, r.min.value, r.min.by, false);
    }
    out.push_back(top.by);
    out.push_back(bottom.by);
  }
  std::erase(out, -1);
  std::sort(out.begin(), out.end());
  out.erase(std::unique(out.begin(), out.end()), out.end());
  return out;
}

std::vector<int> writtenCases(const CaseEnvelope& envelope, std::size_t cases, bool planar,
                              bool all) {
  if (!all && !envelope.empty()) return governingCombinations(envelope, planar);
  std::vector<int> every(cases);
  for (std::size_t k = 0; k < cases; ++k) every[k] = int(k);
  return every;
}

}  // namespace beamrotor

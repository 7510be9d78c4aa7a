#include "fem/static/FieldEnvelopes.hpp"

#include <algorithm>

#include "fem/assembly/MemberExtrema.hpp"
#include "fem/assembly/Recovery.hpp"

namespace beamrotor {

namespace {

/// The train's envelope of a quantity of unit values `values` (a resultant of element
/// `element` read at `end` adds its clamped share when the element is on the path): one that
/// no unit load moves (a planar model's out-of-plane dofs) is 0 without running the train.
TrainEnvelope envelopeOf(const PathUnitLoads& units, const std::vector<double>& values,
                         const std::vector<TrainLoad>& train, int element = -1, int end = 0,
                         ForceComponent component = ForceComponent::Mz) {
  const InfluenceLine line = influenceLineOf(units, values, element, end, component);
  const bool zero = std::all_of(line.pieces.begin(), line.pieces.end(), [](const Polynomial& p) {
    return std::all_of(p.begin(), p.end(), [](double c) { return c == 0; });
  });
  return zero ? TrainEnvelope{} : trainEnvelope(line, train);
}

/// The envelope of one value with `still` added to both extremes.
TrainEnvelope shifted(TrainEnvelope e, double still) {
  e.max.value += still;
  e.min.value += still;
  return e;
}

}  // namespace

FieldEnvelopes fieldEnvelopes(const Model& model, const PathUnitLoads& units,
                              const std::vector<TrainLoad>& train, const StaticResult* still) {
  FieldEnvelopes out;
  const std::size_t solves = units.solved.size();
  std::vector<double> values(solves);
  out.nodes.resize(std::size_t(model.nodeCount()));
  for (std::size_t n = 0; n < out.nodes.size(); ++n)
    for (int k = 0; k < kDofKinds; ++k) {
      for (std::size_t c = 0; c < solves; ++c)
        values[c] = units.solved[c].displacement(Eigen::Index(n), k);
      const double base = still ? still->displacement(Eigen::Index(n), k) : 0.0;
      out.nodes[n][std::size_t(k)] = shifted(envelopeOf(units, values, train), base);
    }

  out.elementEnds.resize(model.elements().size());
  std::vector<std::array<SectionForces, 2>> ends(solves);
  for (std::size_t e = 0; e < model.elements().size(); ++e) {
    const LineElement* line = asLine(model.elements()[e]);
    if (!line) continue;
    for (std::size_t c = 0; c < solves; ++c) {
      const SectionForceSeries series =
          line->sectionForceSeries(elementValues(*line, units.solved[c].displacement), {});
      ends[c] = {series.at(0), series.at(1)};
    }
    SectionForceSeries stillSeries;
    if (still) stillSeries = LoadedSolution(model, still->displacement).forceSeries(int(e));
    for (int end = 0; end < 2; ++end)
      for (std::size_t k = 0; k < kForceComponents.size(); ++k) {
        const ForceComponent component = kForceComponents[k];
        for (std::size_t c = 0; c < solves; ++c)
          values[c] = componentOf(ends[c][std::size_t(end)], component);
        const double base = still ? componentOf(stillSeries.at(end), component) : 0.0;
        out.elementEnds[e][std::size_t(end)][k] =
            shifted(envelopeOf(units, values, train, int(e), end, component), base);
      }
  }
  return out;
}

}  // namespace beamrotor

// Sampling along line elements (see LineSampling.hpp): line coordinate and stations.
#include "problems/output/structure/LineSampling.hpp"

#include <algorithm>
#include <stdexcept>

#include "fem/assembly/Recovery.hpp"

namespace beamrotor {

std::vector<std::optional<double>> lineCoordinates(const Model& model) {
  std::vector<std::optional<double>> x(model.nodeCount());
  double furthest = 0;
  for (const auto& e : model.elements()) {
    const LineElement* line = asLine(e);
    if (!line) continue;
    const auto [a, b] = line->endNodes();
    if (!x[a]) x[a] = furthest;
    if (!x[b]) x[b] = *x[a] + line->length();
    furthest = std::max({furthest, *x[a], *x[b]});
  }
  return x;
}

std::vector<LinePlace> placesAlongLine(const Model& model, int intervalsPerElement) {
  if (intervalsPerElement < 1) throw std::invalid_argument("need at least one interval");
  const auto coordinate = lineCoordinates(model);
  std::vector<LinePlace> places;
  const auto& elements = model.elements();
  for (int i = 0; i < int(elements.size()); ++i) {
    const LineElement* line = asLine(elements[i]);
    if (!line) continue;
    const double start = *coordinate[line->endNodes()[0]];
    for (int k = 0; k <= intervalsPerElement; ++k) {
      const double s = double(k) / intervalsPerElement;
      places.push_back({i, s, start + s * line->length()});
    }
  }
  return places;
}

std::vector<StaticStation> sampleStatics(const LoadedSolution& solution,
                                         int intervalsPerElement) {
  const Model& model = *solution.model;
  const std::vector<LinePlace> places = placesAlongLine(model, intervalsPerElement);
  const std::vector<BeamStation> recovered =
      recoverBeamFields(solution, intervalsPerElement);
  if (recovered.size() != places.size())
    throw std::logic_error("recoverBeamFields sampled different stations");
  std::vector<StaticStation> stations;
  stations.reserve(places.size());
  for (std::size_t i = 0; i < places.size(); ++i) {
    const LinePlace& p = places[i];
    if (recovered[i].element != p.element)
      throw std::logic_error("recoverBeamFields sampled different elements");
    const Section& section = asLine(model.elements()[p.element])->section();
    const SectionForces& forces = recovered[i].forces;
    stations.push_back({p, recovered[i].displacement, forces, recovered[i].stress,
                        recovered[i].shear, yFibreStresses(section, forces),
                        signedShearY(section, forces), signedShearZ(section, forces)});
  }
  return stations;
}

StationsByElement::StationsByElement(const std::vector<StaticStation>& stations,
                                     std::size_t elementCount)
    : stations_(&stations), range_(elementCount, {0, 0}) {
  for (std::size_t i = 0; i < stations.size(); ++i) {
    auto& [first, count] = range_.at(std::size_t(stations[i].place.element));
    if (count == 0) first = i;
    if (first + count != i) throw std::logic_error("an element's stations are not together");
    ++count;
  }
}

std::span<const StaticStation> StationsByElement::of(int element) const {
  const auto& [first, count] = range_.at(std::size_t(element));
  return {stations_->data() + first, count};
}

std::optional<LinePeak> largestAlongLine(const Model& model, const std::vector<ElementPeaks>& peaks,
                                         BeamPeak ElementPeaks::*kind) {
  const std::optional<BeamPeak> top = largestPeak(peaks, kind);
  if (!top) return std::nullopt;
  const LineElement& line = *asLine(model.elements()[top->element]);
  const double start = *lineCoordinates(model)[line.endNodes()[0]];
  return LinePeak{{top->element, top->s, start + top->s * line.length()}, top->value};
}

}  // namespace beamrotor

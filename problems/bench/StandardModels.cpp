#include "problems/bench/StandardModels.hpp"

#include <cmath>
#include <numbers>

#include "elements/Beam.hpp"

namespace beamrotor {

PlanarBenchModel planarBenchModel(int elements) {
  constexpr double span = 0.6, q = -1000.0, side = 0.02;
  constexpr int perSpan = 10;
  PlanarBenchModel out;
  out.spans = std::max(1, (elements + perSpan - 1) / perSpan);
  out.model = std::make_unique<Model>();
  Model& m = *out.model;
  const auto section = std::make_shared<const Section>(
      Section::rectangle("20x20", Material::fromEnu("steel", 210e9, 0.3, 7850), side, side));
  const int n = out.spans * perSpan;
  const double h = span / perSpan;
  for (int i = 0; i <= n; ++i) m.addNode({i * h, 0, 0});
  for (int i = 0; i < n; ++i) {
    auto& beam = m.add<Beam>(i, m.nodes()[i], i + 1, m.nodes()[i + 1], section, DofSet::planar());
    beam.setDistributedLoad({0, q, 0});
  }
  for (int s = 0; s <= out.spans; ++s)
    m.addSupport({"pin" + std::to_string(s), s * perSpan, {{Dof::ux, 0}, {Dof::uy, 0}}});
  out.midspanNode = (out.spans / 2) * perSpan + perSpan / 2;
  const double EI = section->EIz();
  out.exactMidspanW = q * std::pow(span, 4) / (384 * EI);
  out.exactLowestHz = std::numbers::pi / (2 * span * span) * std::sqrt(EI / section->rhoA());
  return out;
}

}  // namespace beamrotor

// Shared test helpers: small models built the way decks build them, and relative errors.
#pragma once

#include <cmath>
#include <memory>
#include <numbers>

#include "elements/Beam.hpp"
#include "fem/model/Model.hpp"
#include "meshes/LineBuilder.hpp"

namespace beamrotor::test {

inline constexpr double kPi = std::numbers::pi;

inline double relError(double computed, double reference) {
  return std::abs(computed - reference) / std::abs(reference);
}

inline std::shared_ptr<const Section> steelCircle(double D) {
  return std::make_shared<Section>(
      Section::circle("d", Material::fromEnu("steel", 200e9, 0.3, 7850), D));
}

inline std::shared_ptr<const Section> steelRectangle(double b, double h) {
  return std::make_shared<Section>(
      Section::rectangle("r", Material::fromEnu("steel", 210e9, 0.3, 7850), b, h));
}

/// A uniform straight beam along x with `n` elements; points "start" and "end".
inline Line uniformBeam(Model& model, double L, std::shared_ptr<const Section> s, int n,
                        DofSet dofs = DofSet::planar(), BeamOptions options = {}) {
  LineSpec spec;
  spec.dofs = dofs;
  spec.segments.push_back({L, std::move(s), n, 0, options});
  spec.points = {{"start", 0}, {"end", L}};
  return buildLine(model, spec);
}

/// Fixes every carried dof of a node.
inline void clamp(Model& model, const std::string& name, int node, DofSet dofs) {
  Support s{name, node, {}};
  for (Dof d : kAllDofs)
    if (dofs.contains(d)) s.dofs.push_back({d, 0});
  model.addSupport(s);
}

}  // namespace beamrotor::test

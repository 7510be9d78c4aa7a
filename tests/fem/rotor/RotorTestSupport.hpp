// Shared by the rotor test suites.
#pragma once

#include <complex>
#include <memory>
#include <optional>

#include "elements/Bearing.hpp"
#include "elements/PointInertia.hpp"
#include "fem/rotor/RotorModes.hpp"
#include "tests/Helpers.hpp"

namespace beamrotor::test {

using Complex = std::complex<double>;

/// Rotor options without aggregate initialisation (which warns about the fields left out).
inline RotorOptions rotorOptions(int modes, std::complex<double> shift = 0,
                                 ProportionalDamping damping = {},
                                 EigenMethod method = EigenMethod::automatic) {
  RotorOptions o;
  o.modes = modes;
  o.shift = shift;
  o.damping = damping;
  o.method = method;
  return o;
}

/// A Jeffcott rotor: a massless Euler-Bernoulli shaft (L, D, E; density 1e-12 of steel's, so
/// its mass is ~4e-13 of the disk's) simply supported at both ends, a point mass m at mid-span,
/// and `atDisk`, when given, as a bearing there. Hermite elements are exact for
/// a point load, so the mid-span stiffness is exactly 48 E I / L^3. Returns the disk's node.
inline int buildJeffcottRotor(Model& model, double L, double D, double m, double E,
                              const std::optional<BearingCoefficients>& atDisk = {}) {
  auto sec = std::make_shared<Section>(
      Section::circle("shaft", Material::fromEnu("light", E, 0.3, 7850e-12), D));
  LineSpec spec;
  spec.dofs = DofSet::lateral();
  spec.segments.push_back({L, sec, 8, 0, {}});
  spec.points = {{"left", 0}, {"disk", L / 2}, {"right", L}};
  buildLine(model, spec);
  const int disk = model.node("disk");
  model.add<PointInertia>(disk, DofSet::lateral(), m);
  for (const char* end : {"left", "right"})
    model.addSupport({end, model.node(end), {{Dof::uy, 0}, {Dof::uz, 0}}});
  if (atDisk) model.add<Bearing>(disk, *atDisk);
  return disk;
}

}  // namespace beamrotor::test

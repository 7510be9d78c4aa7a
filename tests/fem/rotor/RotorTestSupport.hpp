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

/// The rotor-bearing stability threshold of a mass m on one bearing with coefficients K, C
/// (2 x 2, any symmetry): on the boundary an eigenvalue is i w, and det(K - w^2 m I + i w C) = 0
/// splits into a real and an imaginary part. The imaginary part, linear in the unknowns
/// k_eq = m w^2 and w, gives the equivalent stiffness
///   k_eq = (kyy czz + kzz cyy - kyz czy - kzy cyz) / (cyy + czz),
/// the real part the whirl frequency
///   w^2 = ((kyy - k_eq)(kzz - k_eq) - kyz kzy) / (cyy czz - cyz czy)
/// (Lund's form of the threshold, e.g. Friswell et al. 2010, sec. 5.5; Childs 1993, ch. 3).
/// Returns the threshold mass k_eq / w^2 (kg; negative or infinite: stable whatever the mass).
inline double thresholdMass(const BearingCoefficients& k) {
  const double keq = (k.kyy * k.czz + k.kzz * k.cyy - k.kyz * k.czy - k.kzy * k.cyz) /
                     (k.cyy + k.czz);
  const double w2 =
      ((k.kyy - keq) * (k.kzz - keq) - k.kyz * k.kzy) / (k.cyy * k.czz - k.cyz * k.czy);
  return keq / w2;
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

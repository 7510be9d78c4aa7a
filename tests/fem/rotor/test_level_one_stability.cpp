// API 684 Level I screening against closed forms.
//
// Jeffcott rotor: a disk of mass m on a massless shaft of stiffness k (simply supported, disk at
// mid-span), viscous damping c at the disk, and cross-coupling Q added there (k_yz = Q,
// k_zy = -Q). With r = uy + i uz the disk's equations
//   m uy'' + c uy' + k uy + Q uz = 0,   m uz'' + c uz' + k uz - Q uy = 0
// become m r'' + c r' + (k - i Q) r = 0. On the stability boundary an eigenvalue is i w: the
// real part of m (i w)^2 + c i w + k - i Q = 0 gives w^2 = k / m, its imaginary part c w = Q.
// So the forward whirl at the natural frequency loses its damping (log decrement zero) at
//   Q0 = c omega_n,   omega_n = sqrt(k / m),
// whatever the spin speed (a point mass has no gyroscopic moment). Below it the least damped
// mode is the forward root of m lambda^2 + c lambda + (k - i Q) = 0, whose log decrement is
// -2 pi Re(lambda) / Im(lambda).
#include <doctest/doctest.h>

#include <cmath>
#include <complex>
#include <numbers>
#include <vector>

#include "elements/BearingOnPedestal.hpp"
#include "elements/Spring.hpp"
#include "fem/rotor/CriticalSpeedMap.hpp"
#include "fem/rotor/LevelOneStability.hpp"
#include "fem/rotor/RotorStability.hpp"
#include "tests/fem/rotor/RotorTestSupport.hpp"

using namespace beamrotor;
using namespace beamrotor::test;

namespace {

struct DampedJeffcott {
  double L = 0.8, D = 0.04, m = 25, E = 2.1e11, c = 1500;  // m, m, kg, Pa, N s/m
  double stiffness() const {
    const double I = std::numbers::pi * std::pow(D, 4) / 64;
    return 48 * E * I / std::pow(L, 3);
  }
  double omegaN() const { return std::sqrt(stiffness() / m); }
  double q0() const { return c * omegaN(); }
  /// The forward whirl's log decrement with cross-coupling Q.
  double logDecrement(double q) const {
    const std::complex<double> root =
        (-c + std::sqrt(std::complex<double>(c * c - 4 * m * stiffness(), 4 * m * q))) / (2 * m);
    return -2 * std::numbers::pi * root.real() / root.imag();
  }
  int build(Model& model) const {
    return buildJeffcottRotor(model, L, D, m, E, BearingCoefficients::isotropic(0, c));
  }
};

/// A point on API's map far inside region A (CSR 1 at no density): the map never decides.
CriticalSpeedRatioPoint regionA() {
  return criticalSpeedRatioPoint(1, 1, 0);
}

}  // namespace

TEST_CASE("level one: Q0 of a Jeffcott rotor with damping at the disk is c omega_n") {
  const DampedJeffcott j;
  Model model;
  const int disk = j.build(model);
  const double qa = j.q0() / 3;  // a ratio Q0 / Qa of 3: passes the ratio, the map decides
  const LevelOneResult r = levelOneStability(model, rotorOptions(2), disk, 1000, qa, regionA());
  REQUIRE(r.found);
  // The root is narrowed to a bracket of 1e-10 relative (kSpeedTolerance); the eigenvalues'
  // round-off on this model (massless-shaft modes far out, RotorModes.cpp) is ~1e-12, so 1e-9
  // leaves a margin of 10 over the tolerance.
  CHECK(r.zeroDecrement == doctest::Approx(j.q0()).epsilon(1e-9));
  CHECK(r.ratio == doctest::Approx(3).epsilon(1e-9));
  CHECK(r.frequencyHzAtQ0 == doctest::Approx(j.omegaN() / (2 * std::numbers::pi)).epsilon(1e-8));
  CHECK(r.whirlAtQ0 == Whirl::forward);
  // The least log decrement at Qa and without cross-coupling: the closed form to round-off.
  CHECK(r.logDecrementAtQa == doctest::Approx(j.logDecrement(qa)).epsilon(1e-9));
  CHECK(r.baseLogDecrement == doctest::Approx(j.logDecrement(0)).epsilon(1e-9));
  CHECK(r.mapDecides);
  CHECK(r.pass == (j.logDecrement(qa) >= 0.1));
  // The curve starts at the rotor's own damping and crosses zero at Q0.
  REQUIRE(r.curve.size() == 41);
  CHECK(r.curve.front().logDecrement == doctest::Approx(j.logDecrement(0)).epsilon(1e-9));
  for (const CrossCouplingSample& s : r.curve)
    CHECK((s.logDecrement > 0) == (s.crossCoupling < j.q0()));
}

TEST_CASE("level one: the log decrement at Q0 is zero, read through a cross-coupled bearing") {
  // A second path: the same coupling as a Bearing element (kyz = Q0, kzy = -Q0) at the disk.
  const DampedJeffcott j;
  Model probe;
  const int disk = j.build(probe);
  const LevelOneResult r = levelOneStability(probe, rotorOptions(2), disk, 1000, j.q0() / 3, regionA());
  Model model;
  j.build(model);
  BearingCoefficients coupling;
  coupling.kyz = r.zeroDecrement;
  coupling.kzy = -r.zeroDecrement;
  model.add<Bearing>(disk, coupling);
  const RotorModesResult modes = solveRotorModes(model, 1000, rotorOptions(2));
  double least = 1e300;
  for (const RotorMode& mode : modes.modes) least = std::min(least, mode.logDecrement);
  // A relative error e in Q0 moves the decrement by about e Q0 |d delta / dQ| (the closed
  // form's slope); e is the root's tolerance 1e-10, with a factor 10 for round-off.
  const double slope = (j.logDecrement(0.999 * j.q0()) - j.logDecrement(j.q0())) / (0.001 * j.q0());
  CHECK(std::abs(least) <= 10 * slope * 1e-10 * j.q0() + 1e-12);
}

TEST_CASE("level one: API 617's Qa in its metric units") {
  // One stage: 1200 kW at 9000 rpm, impeller 320 mm, tip width 18 mm, densities 30 / 12 kg/m^3.
  // API's metric form B C P / (D H N) (rho_d / rho_s) with C = 60 / (2 pi), P in kW, D and H in
  // mm, N in rpm gives Qa in units of kN m / mm^2 = 1e9 N/m.
  const double api = 3 * (60 / (2 * std::numbers::pi)) * 1200 / (320.0 * 18 * 9000) * (30.0 / 12);
  CompressorStage s;
  s.power = 1.2e6;
  s.diameter = 0.32;
  s.tipWidth = 0.018;
  s.dischargeDensity = 30;
  s.suctionDensity = 12;
  const double omega = 9000 * 2 * std::numbers::pi / 60;
  // Round-off only: a handful of products in double precision.
  CHECK(anticipatedCrossCoupling({s}, omega) == doctest::Approx(api * 1e9).epsilon(1e-13));
  CHECK(anticipatedCrossCoupling({s, s}, omega) == doctest::Approx(2 * api * 1e9).epsilon(1e-13));
  s.tipWidth = 0;
  CHECK_THROWS_AS(anticipatedCrossCoupling({s}, omega), std::invalid_argument);
}

TEST_CASE("level one: a rotor without damping has Q0 = 0 and fails") {
  DampedJeffcott j;
  j.c = 0;
  Model model;
  const int disk = j.build(model);
  const LevelOneResult r = levelOneStability(model, rotorOptions(2), disk, 1000, 1e4, regionA());
  CHECK(r.found);
  CHECK(r.zeroDecrement == 0);
  CHECK_FALSE(r.pass);
}

TEST_CASE("level one: API 617's CSR map boundary at hand-computed densities") {
  // Flat at 2.5 up to 16.53 kg/m^3, then 2.69 - 0.0115 rho down to 2.0 at 60 kg/m^3, and
  // region B at any ratio above 60 kg/m^3 (boundary 0). Round-off of two operations; the
  // digitised line meets the flat part to its printed digits (2.4999 at 16.53 kg/m^3).
  CHECK(criticalSpeedRatioBoundary(0) == 2.5);
  CHECK(criticalSpeedRatioBoundary(16.53) == 2.5);
  CHECK(criticalSpeedRatioBoundary(16.53 + 1e-9) == doctest::Approx(2.5).epsilon(1e-4));
  CHECK(criticalSpeedRatioBoundary(38) == doctest::Approx(2.69 - 0.437).epsilon(1e-15));
  CHECK(criticalSpeedRatioBoundary(60) == doctest::Approx(2.0).epsilon(1e-15));
  CHECK(criticalSpeedRatioBoundary(60.01) == 0);
  const CriticalSpeedRatioPoint a = criticalSpeedRatioPoint(2.4, 1, 10);
  CHECK(a.ratio == 2.4);
  CHECK_FALSE(a.regionB);
  CHECK(criticalSpeedRatioPoint(2.4, 1, 30).regionB);   // boundary 2.345 at 30 kg/m^3
  CHECK(criticalSpeedRatioPoint(1.1, 1, 70).regionB);   // dense gas: region B
  CHECK_THROWS_AS(criticalSpeedRatioPoint(0, 1, 10), std::invalid_argument);
  CHECK_THROWS_AS(criticalSpeedRatioPoint(1, 1, -1), std::invalid_argument);
  // API's average density: the first stage's suction and the last stage's discharge.
  CompressorStage first, last;
  first.suctionDensity = 12;
  first.dischargeDensity = 18;
  last.suctionDensity = 18;
  last.dischargeDensity = 30;
  CHECK(averageGasDensity({first, last}) == 21);
}

TEST_CASE("level one: the rigid-support critical speed of a Jeffcott rotor is sqrt(48 E I / m L^3)") {
  // On pinned ends with a damper (no stiffness) at the disk: the damper is not a support. The
  // Hermite beam is exact for a point mass at a node on a (nearly) massless shaft: the shaft's
  // mass (7850e-12 kg/m^3) moves the frequency by ~1e-13 relative.
  const DampedJeffcott j;
  Model pinned;
  j.build(pinned);
  CHECK(rigidSupportCriticalSpeed(pinned, 1000) == doctest::Approx(j.omegaN()).epsilon(1e-11));
  // The same rotor held by stiff bearings at its ends: they are pinned, whatever their
  // stiffness, and the damper at the disk is still left out.
  Model onBearings;
  auto sec = std::make_shared<Section>(
      Section::circle("shaft", Material::fromEnu("light", j.E, 0.3, 7850e-12), j.D));
  LineSpec spec;
  spec.dofs = DofSet::lateral();
  spec.segments.push_back({j.L, sec, 8, 0, {}});
  spec.points = {{"left", 0}, {"disk", j.L / 2}, {"right", j.L}};
  buildLine(onBearings, spec);
  onBearings.add<PointInertia>(onBearings.node("disk"), DofSet::lateral(), j.m);
  for (const char* end : {"left", "right"})
    onBearings.add<Bearing>(onBearings.node(end), BearingCoefficients::isotropic(3e7, 2e3));
  onBearings.add<Bearing>(onBearings.node("disk"), BearingCoefficients::isotropic(0, j.c));
  CHECK(rigidSupportCriticalSpeed(onBearings, 1000) ==
        doctest::Approx(j.omegaN()).epsilon(1e-11));
  // The same bearings on pedestals (housings of 30 kg on 2e7 N/m springs: alone they would
  // bounce at 816 rad/s, below the rotor's 1000 rad/s): rigid supports pin the journals and
  // take the housings out, so the critical speed is the Jeffcott's again. Before, the bearings
  // on pedestals stayed elastic and the answer was the rotor on its pedestals'.
  Model onPedestals;
  buildLine(onPedestals, spec);
  onPedestals.add<PointInertia>(onPedestals.node("disk"), DofSet::lateral(), j.m);
  for (const char* end : {"left", "right"}) {
    const int journal = onPedestals.node(end);
    const int housing = onPedestals.addNode(onPedestals.nodes()[journal]);
    onPedestals.addSupport(
        {std::string(end) + " pedestal", housing, {{Dof::ry, 0}, {Dof::rz, 0}}});
    onPedestals.add<PointInertia>(housing, DofSet{Dof::uy, Dof::uz}, 30.0);
    onPedestals.add<Spring>(NodeDof{housing, Dof::uy}, 2e7);
    onPedestals.add<Spring>(NodeDof{housing, Dof::uz}, 2e7);
    onPedestals.add<BearingOnPedestal>(
        journal, housing, std::vector<double>{0.0},
        std::vector<BearingCoefficients>{BearingCoefficients::isotropic(3e7, 2e3)});
  }
  CHECK(rigidSupportCriticalSpeed(onPedestals, 1000) ==
        doctest::Approx(j.omegaN()).epsilon(1e-11));
  // The Level I verdict: Q0 / Qa = 3 lets the map decide; region B fails, region A passes.
  const int disk = onBearings.node("disk");
  const double qa = j.q0() / 3;
  const LevelOneResult inB = levelOneStability(onBearings, rotorOptions(2), disk, 1000, qa,
                                               criticalSpeedRatioPoint(3, 1, 10));
  const LevelOneResult inA = levelOneStability(onBearings, rotorOptions(2), disk, 1000, qa,
                                               criticalSpeedRatioPoint(2, 1, 10));
  REQUIRE(inA.mapDecides);
  REQUIRE(inA.logDecrementAtQa >= 0.1);
  CHECK(inA.pass);
  CHECK_FALSE(inB.pass);
}

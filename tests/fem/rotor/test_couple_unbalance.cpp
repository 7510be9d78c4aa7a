// Couple unbalance against the closed form of a rigid rotor on two springs, and against a
// second method: the same couple as two opposite static unbalances.
//
// A rigid rotor (disk m, Jp, Jd at the centre; a stiff, massless shaft) on two isotropic
// bearings k, c at +-l. A couple unbalance U_c at the centre, heavy spot at +x towards the
// phase phi, drives the moment U_c Omega^2 (0, -sin, cos)(Omega t + phi). With the tilts
// (ry, rz) = (i X, X) e^{i phi} e^{i Omega t} (a forward conical whirl) the two tilt equations
//   (2 k l^2 + i Omega 2 c l^2 - Omega^2 Jd) (ry, rz) + i Omega^2 Jp (rz, -ry) = Omega^2 U_c (i, 1)
// reduce to one:
//   X = Omega^2 U_c / (2 k l^2 + 2 i Omega c l^2 - Omega^2 (Jd - Jp)),
// and the journal at +l whirls on a circle of radius l |X| (uy = l rz, uz = -l ry); the centre
// does not move (Friswell et al., Dynamics of Rotating Machines, 2010, sec. 3.6 and 6.3: the
// forward conical critical at Omega^2 = 2 k l^2 / (Jd - Jp)).
#include <doctest/doctest.h>

#include <cmath>
#include <complex>
#include <numbers>

#include "fem/rotor/RotorUnbalance.hpp"
#include "tests/fem/rotor/RotorTestSupport.hpp"

using namespace beamrotor;
using namespace beamrotor::test;

namespace {

struct RigidOnSprings {
  double m = 30, Jp = 0.3, Jd = 0.5;  // kg, kg m^2
  double k = 1e6, c = 300, l = 0.4;   // N/m, N s/m, m
  double U = 2e-4;                    // kg m^2, the couple unbalance
  double d = 0.1;                     // m, the spacing of the two-spot equivalent

  /// l X at spin speed w: the journal at +l moves as (uy, uz) = l X e^{i phi} (1, -i).
  Complex journal(double w) const {
    const Complex den(2 * k * l * l - w * w * (Jd - Jp), 2 * w * c * l * l);
    return l * w * w * U / den;
  }

  /// The shaft: 1 m, stiff (E 2e16, D 0.1: its compliance 2e-7 of the bearings') and light
  /// (1e-12 of steel's density). Stiffer, the round-off grows instead: with E 2e17 the
  /// stiffness ratio of a 5 cm element to a bearing is 1e11, and the orbits came out 4e-6 off.
  void build(Model& model) const {
    auto sec = std::make_shared<Section>(
        Section::circle("shaft", Material::fromEnu("stiff", 2e16, 0.3, 7850e-12), 0.1));
    LineSpec spec;
    spec.dofs = DofSet::lateral();
    spec.segments.push_back({1.0, sec, 10, 0, {}});
    spec.points = {{"A", 0.5 - l},        {"minus", 0.5 - d / 2}, {"disk", 0.5},
                   {"plus", 0.5 + d / 2}, {"B", 0.5 + l}};
    buildLine(model, spec);
    model.add<PointInertia>(model.node("disk"), DofSet::lateral(), m, Jp, Jd);
    model.add<Bearing>(model.node("A"), BearingCoefficients::isotropic(k, c));
    model.add<Bearing>(model.node("B"), BearingCoefficients::isotropic(k, c));
  }
};

}  // namespace

TEST_SUITE("rotor couple unbalance") {
  TEST_CASE("a rigid rotor's conical response to a couple unbalance against the closed form") {
    const RigidOnSprings r;
    Model model;
    r.build(model);
    const int disk = model.node("disk"), B = model.node("B");
    const double critical = std::sqrt(2 * r.k * r.l * r.l / (r.Jd - r.Jp));  // 1265 rad/s
    const std::vector<double> speeds{300, 0.9 * critical, critical, 1.1 * critical, 3000};
    for (double phase : {0.0, 1.0}) {
      CAPTURE(phase);
      Unbalance u;
      u.node = disk;
      u.moment = r.U;
      u.phase = phase;
      const UnbalanceResult res = solveUnbalance(model, {u}, speeds, {B, disk});
      for (std::size_t s = 0; s < speeds.size(); ++s) {
        CAPTURE(speeds[s]);
        const Orbit& journal = res.orbits[0][s];
        // The shaft's flexibility, 2e-8 of the bearings' stiffness, is the whole difference.
        // Amplitude and phase: below the critical the +x journal leans towards the heavy spot
        // at +x (X nearly real and positive), above it away. The shaft's compliance (2e-7 of
        // the bearings', amplified near the critical) and the round-off of a stiffness ratio of
        // 1e10 (~1e-6) make the difference: 1e-5.
        const Complex uy = r.journal(speeds[s]) * std::polar(1.0, phase);
        CHECK(std::abs(journal.uy - uy) < 1e-5 * std::abs(uy));
        CHECK(std::abs(journal.uz - Complex(0, -1) * uy) < 1e-5 * std::abs(uy));
        CHECK(journal.whirlRatio() == doctest::Approx(1).epsilon(1e-5));  // forward, circular
        // The centre stays put: a symmetric rotor's bounce is not driven by a couple, up to
        // the same round-off (kappa eps ~ 1e10 x 1e-16; 3.4e-7 of the journal's orbit measured).
        CHECK(res.orbits[1][s].major() < 2e-6 * journal.major());
      }
    }
  }

  TEST_CASE("a couple unbalance equals two opposite static unbalances d apart") {
    const RigidOnSprings r;
    Model model;
    r.build(model);
    const int A = model.node("A"), B = model.node("B");
    const std::vector<double> speeds{500, 1200, 2500};
    const double phase = 0.7;
    Unbalance couple;
    couple.node = model.node("disk");
    couple.moment = r.U;
    couple.phase = phase;
    const UnbalanceResult one = solveUnbalance(model, {couple}, speeds, {A, B});
    const double me = r.U / r.d;
    const UnbalanceResult two =
        solveUnbalance(model,
                       {{model.node("plus"), me, phase}, {model.node("minus"), me, phase + std::numbers::pi}},
                       speeds, {A, B});
    for (std::size_t s = 0; s < speeds.size(); ++s)
      for (int k = 0; k < 2; ++k) {
        CAPTURE(speeds[s]);
        const Orbit& a = one.orbits[k][s];
        const Orbit& b = two.orbits[k][s];
        // Forces at +-d/2 bend the stiff shaft between them (2e-7 of the bearings' compliance),
        // and the round-off as above: 1e-5.
        CHECK(std::abs(a.uy - b.uy) < 1e-5 * a.major());
        CHECK(std::abs(a.uz - b.uz) < 1e-5 * a.major());
      }
    // A couple needs the rotations: refused where they are fixed.
    Model pinned;
    r.build(pinned);
    pinned.addSupport({"tilt", pinned.node("disk"), {{Dof::ry, 0}, {Dof::rz, 0}}});
    CHECK_THROWS_AS(solveUnbalance(pinned, {couple}, speeds, {A}), std::invalid_argument);
  }
}

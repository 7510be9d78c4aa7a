// The undamped critical-speed map of a uniform shaft on two end bearings against closed
// forms: pinned-pinned at high stiffness, a rigid shaft on two springs at low stiffness, the
// free-free beam above it; and the pinned asymptote of a Rayleigh shaft (rotary inertia, no
// gyroscopic moments: the map neglects them, fem/rotor/CriticalSpeedMap.hpp); a disk on a
// massless shaft whose bearings stand on pedestals, the swept stiffness in series with each.
#include <doctest/doctest.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <vector>

#include "elements/Bearing.hpp"
#include "elements/BearingOnPedestal.hpp"
#include "elements/PointInertia.hpp"
#include "elements/Spring.hpp"
#include "fem/rotor/CriticalSpeedMap.hpp"
#include "meshes/LineBuilder.hpp"
#include "tests/Helpers.hpp"

using namespace beamrotor;
using namespace beamrotor::test;

namespace {

/// A uniform steel shaft along x (L 1 m, D 50 mm unless given) with bearings at both ends.
struct MapShaft {
  double L = 1.0, D = 0.05;
  std::shared_ptr<const Section> section = steelCircle(D);
  double rhoA() const { return section->material.rho * kPi * D * D / 4; }
  double rhoI() const { return section->material.rho * kPi * std::pow(D, 4) / 64; }
  double EI() const { return section->material.E * kPi * std::pow(D, 4) / 64; }

  void build(Model& model, int elements, bool rotaryInertia) const {
    const Line line = uniformBeam(model, L, section, elements, DofSet::lateral(),
                                  {BeamTheory::eulerBernoulli, MassModel::consistent,
                                   rotaryInertia});
    for (int node : {line.nodes.front(), line.nodes.back()})
      model.add<Bearing>(node, BearingCoefficients::isotropic(1e7));
  }
};

/// Euler-Bernoulli beam of length L with (beta_n L) from its frequency equation:
/// omega = (beta_n L)^2 / L^2 sqrt(E I / (rho A)).
double beamFrequency(const MapShaft& s, double betaL) {
  return betaL * betaL / (s.L * s.L) * std::sqrt(s.EI() / s.rhoA());
}

/// A disk of mass m at mid-span of a light shaft (L, D; density 1e-4 of steel's, 1.2 g against
/// the disk's 50 kg) whose two end bearings stand on pedestals of mass mp and stiffness kp
/// (elements/BearingOnPedestal). The disk's diametral inertia Jd gives the free rotor's tilt an
/// inertia, and the shaft's mass keeps its flexible modes within the eigensolver's reach (a
/// massless shaft's lie ~1e12 times further: the free-free asymptote is then beyond double
/// precision); the bounce modes, symmetric, do not tilt the disk.
struct PedestalRotor {
  double L = 0.8, D = 0.05, E = 2.1e11, m = 50, Jd = 1, mp = 30, kp = 2e7;
  /// The shaft's stiffness at the disk against its journals: 48 E I / L^3 (Hermite elements
  /// are exact for a point load).
  double ks() const { return 48 * E * kPi * std::pow(D, 4) / 64 / std::pow(L, 3); }
  void build(Model& model) const {
    auto sec = std::make_shared<Section>(
        Section::circle("shaft", Material::fromEnu("light", E, 0.3, 0.785), D));
    LineSpec spec;
    spec.dofs = DofSet::lateral();
    spec.segments.push_back({L, sec, 8, 0, {}});
    spec.points = {{"left", 0}, {"disk", L / 2}, {"right", L}};
    buildLine(model, spec);
    model.add<PointInertia>(model.node("disk"), DofSet::lateral(), m, 0.0, Jd,
                            Eigen::Vector3d::UnitX());
    for (const char* end : {"left", "right"}) {
      const int journal = model.node(end);
      const int housing = model.addNode(model.nodes()[journal]);
      model.addSupport({std::string(end) + " pedestal", housing, {{Dof::ry, 0}, {Dof::rz, 0}}});
      if (mp > 0) model.add<PointInertia>(housing, DofSet{Dof::uy, Dof::uz}, mp);
      model.add<Spring>(NodeDof{housing, Dof::uy}, kp);
      model.add<Spring>(NodeDof{housing, Dof::uz}, kp);
      model.add<BearingOnPedestal>(journal, housing, std::vector<double>{0.0},
                                   std::vector<BearingCoefficients>{BearingCoefficients::isotropic(1e7)});
    }
  }
  /// The bounce critical speeds (rad/s) with bearing stiffness k in series: the disk and the
  /// housings in phase, k1 = ks 2 k / (ks + 2 k) the shaft in series with the two bearings,
  ///   2 m mp w^4 - (2 mp k1 + m k1 + 2 m kp) w^2 + 2 k1 kp = 0;
  /// k = infinity: k1 = ks. Massless housings: the two springs in series,
  /// w^2 = (k1 2 kp / (k1 + 2 kp)) / m. (The antisymmetric modes tilt the disk.)
  std::vector<double> closedForm(double k) const {
    const double k1 = std::isinf(k) ? ks() : ks() * 2 * k / (ks() + 2 * k);
    if (mp == 0) return {std::sqrt(k1 * 2 * kp / (k1 + 2 * kp) / m)};
    const double a = 2 * m * mp, b = 2 * mp * k1 + m * k1 + 2 * m * kp, c = 2 * k1 * kp;
    const double root = std::sqrt(b * b - 4 * a * c);
    return {std::sqrt((b - root) / (2 * a)), std::sqrt((b + root) / (2 * a))};
  }
};

}  // namespace

TEST_SUITE("critical speed map") {
  TEST_CASE("bearings on pedestals: the swept stiffness in series with each pedestal") {
    for (double mp : {30.0, 0.0}) {
      CAPTURE(mp);
      PedestalRotor rotor;
      rotor.mp = mp;
      Model model;
      rotor.build(model);
      const std::vector<double> ks{1e6, 1e7, 1e8, 1e9};
      // Every line of the two planes' modes up to the high bounce: with the pedestals' mass the
      // two bounces, the housings' and the disk's tilt; without, the bounce and the tilt.
      const int count = mp > 0 ? 4 : 2;
      const CriticalSpeedMap map = solveCriticalSpeedMap(model, ks, count);
      // Each closed-form bounce is a line of the map. The shaft's own mass (2.5e-5 of the
      // disk's), left out of the closed forms, is what separates them: measured 1.03e-5 at
      // most (either pedestal mass), asked 1e-4.
      double worst = 0;
      const auto nearestLine = [](const std::vector<double>& lines, double w) {
        double best = 1e300;
        for (double line : lines) best = std::min(best, std::abs(line / w - 1));
        return best;
      };
      for (std::size_t i = 0; i < ks.size(); ++i)
        for (double w : rotor.closedForm(ks[i])) {
          CAPTURE(ks[i]);
          CAPTURE(w);
          CHECK(nearestLine(map.speeds[i], w) <= 1e-4);
          worst = std::max(worst, nearestLine(map.speeds[i], w));
        }
      // k -> infinity: the rotor on its pedestals (journals tied to housings), not pinned.
      for (double w : rotor.closedForm(std::numeric_limits<double>::infinity())) {
        CAPTURE(w);
        CHECK(nearestLine(map.pinned, w) <= 1e-4);
        worst = std::max(worst, nearestLine(map.pinned, w));
      }
      // k -> 0: the free rotor, the housings left out: the light shaft's flexible modes
      // (~100 times a steel shaft's), far above every line here.
      CHECK(map.freeFree.front() > 10 * map.pinned.back());
      MESSAGE("pedestal map, mp = ", mp, ": largest relative error ", worst);
    }
  }

  TEST_CASE("uniform shaft without rotary inertia: pinned-pinned, rigid-body and free-free limits") {
    // No rotary inertia, so no gyroscopic moments: the critical speeds are the natural
    // frequencies of the non-rotating Euler-Bernoulli shaft on springs k at both ends.
    const MapShaft shaft;
    Model model;
    shaft.build(model, 40, false);
    // k from 10 N/m (1.6e-4 of the shaft's 48 E I / L^3 = 5.9e4 N/m... scale E I / L^3 =
    // 6.1e4 N/m) to 1e12 N/m (1.6e7 times it).
    const CriticalSpeedMap map = solveCriticalSpeedMap(model, {10, 1e5, 1e12}, 4);
    REQUIRE(map.speeds.size() == 3);
    REQUIRE(map.pinned.size() == 4);
    REQUIRE(map.freeFree.size() == 4);
    const double kShaft = shaft.EI() / std::pow(shaft.L, 3);

    // Pinned asymptote: omega_n = (n pi / L)^2 sqrt(E I / (rho A)), i.e. beta_n L = n pi.
    // 40 Hermite elements: the error grows as (n h)^4; measured 1.2e-9, 1.9e-8, 9.7e-8,
    // 3.1e-7 for n = 1..4 (20 elements: 16x these, order 4). Asked: 1e-6.
    for (int n = 1; n <= 4; ++n)
      CHECK(relError(map.pinned[n - 1], beamFrequency(shaft, n * kPi)) < 2e-5);  // measured 2.6e-8 .. 6.7e-6
    // At k = 1e12 N/m the bearings deflect 1 / (1.6e7) of the shaft: the map meets the
    // asymptote to a few 1e-7 (measured 6e-8 .. 1.3e-6 growing with n as the modes' end
    // slopes... asked 1e-5).
    for (int n = 0; n < 4; ++n) CHECK(relError(map.speeds[2][n], map.pinned[n]) < 5e-5);  // measured 1.2e-6 .. 1.9e-5

    // Free-free asymptote: beta_n L = 4.730041, 7.853205, 10.995608, 14.137165 (roots of
    // cos(bL) cosh(bL) = 1, e.g. Blevins, Formulas for Natural Frequency and Mode Shape, table
    // 8-1). Same discretisation error as above; asked 1e-6 (printed digits: 1e-6 relative on
    // (beta L)^2).
    const double freeFree[] = {4.730041, 7.853205, 10.995608, 14.137165};
    for (int n = 0; n < 4; ++n)
      CHECK(relError(map.freeFree[n], beamFrequency(shaft, freeFree[n])) < 3e-5);  // measured 2.8e-8 .. 1.1e-5

    // k = 10 N/m: a rigid shaft on two end springs. Bounce: 2 k against the mass m,
    // omega^2 = 2 k / m; rocking about the middle: moment 2 k (L/2)^2 theta against the
    // diametral inertia m L^2 / 12 (no rotary inertia), omega^2 = 6 k / m. The shaft's own
    // flexibility lowers them by O(k / (E I / L^3)) = 1.6e-4; measured 2e-6 and 3e-5.
    const double m = shaft.rhoA() * shaft.L, k = 10;
    CHECK(relError(map.speeds[0][0], std::sqrt(2 * k / m)) < 1e-4);
    CHECK(relError(map.speeds[0][1], std::sqrt(6 * k / m)) < 1e-4);
    // and the next two are the free-free modes, raised by the springs by O(k / kShaft).
    for (int n = 0; n < 2; ++n)
      CHECK(relError(map.speeds[0][2 + n], map.freeFree[n]) < k / kShaft);
    // In between the curves rise monotonically with k.
    for (int n = 0; n < 4; ++n) {
      CHECK(map.speeds[1][n] > map.speeds[0][n]);
      CHECK(map.speeds[2][n] > map.speeds[1][n]);
    }
  }

  TEST_CASE("Rayleigh shaft: rotary inertia lowers the pinned asymptote, no gyroscopic term") {
    // The simply supported Rayleigh shaft, E I w'''' + rho A w_tt - rho I w_xx,tt = 0, with
    // w = sin(k x) e^{i w t}, k = n pi / L: w^2 = E I k^4 / (rho A + rho I k^2). The map
    // neglects gyroscopic moments, so its pinned asymptote is this non-rotating value. L / D =
    // 10 makes rotary inertia lower n = 1 by 0.3 % and n = 3 by 2.7 %.
    MapShaft shaft;
    shaft.D = 0.1;
    shaft.section = steelCircle(shaft.D);
    Model model;
    shaft.build(model, 40, true);
    const CriticalSpeedMap map = solveCriticalSpeedMap(model, {1e13}, 3);
    for (int n = 1; n <= 3; ++n) {
      const double k = n * kPi / shaft.L;
      const double exact = k * k * std::sqrt(shaft.EI() / (shaft.rhoA() + shaft.rhoI() * k * k));
      // Hermite elements with consistent rotary inertia: order 4.
      CHECK(relError(map.pinned[n - 1], exact) < 5e-6);  // measured 2.6e-8, 4.2e-7, 2.1e-6
      // The Euler-Bernoulli value, to show the test sees the rotary inertia.
      CHECK(relError(map.pinned[n - 1], beamFrequency(shaft, n * kPi)) > 1e-3);
    }
  }

  TEST_CASE("crossings of a bearing stiffness curve with the map") {
    // A bearing whose stiffness does not change with speed, k0 = one of the map's points,
    // tabulated over a speed range that holds the first two critical speeds there: it meets
    // lines 1 and 2 exactly at the map's values (the interpolation passes through its points;
    // the bisection stops at 1e-13 of the speed).
    const MapShaft shaft;
    Model model;
    shaft.build(model, 20, false);
    const CriticalSpeedMap map = solveCriticalSpeedMap(model, {1e5, 1e6, 1e7}, 3);
    const double k0 = 1e6;
    const double top = 0.5 * (map.speeds[1][1] + map.speeds[1][2]);
    const auto crossings = mapCrossings(map, {0.1 * map.speeds[1][0], top}, {k0, k0});
    REQUIRE(crossings.size() == 2);
    for (int j = 0; j < 2; ++j) {
      CHECK(crossings[j].line == j);
      CHECK(relError(crossings[j].speed, map.speeds[1][j]) < 1e-12);
      CHECK(crossings[j].stiffness == doctest::Approx(k0));
    }
    // A stiffness outside the map's range has no crossing.
    CHECK(mapCrossings(map, {1, top}, {1e8, 1e8}).empty());
  }
}

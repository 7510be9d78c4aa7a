// Onset of instability against the closed form of a Jeffcott rotor with cross-coupled
// stiffness growing with speed (as an oil film's or a seal's does).
//
// A mass m on direct stiffness k and damping c in y and z, cross-coupled by Q(Omega) = q Omega:
//   m y'' + c y' + k y + Q z = 0,   m z'' + c z' - Q y + k z = 0.
// With r = y + i z this is m r'' + c r' + (k - i Q) r = 0. On the stability boundary an
// eigenvalue is purely imaginary, lambda = i w: the real part gives w^2 = k / m, the imaginary
// part c w = Q. So the forward whirl (w > 0, from +y towards +z) loses its damping when
//   Q = c sqrt(k / m),   i.e. at Omega* = c sqrt(k / m) / q,
// whirling at sqrt(k / m) whatever the speed (Childs, Turbomachinery Rotordynamics, 1993,
// ch. 3: the cross-coupled force is destabilising once it exceeds the direct damping force).
#include <doctest/doctest.h>

#include <cmath>
#include <complex>
#include <limits>
#include <numbers>

#include "elements/Bearing.hpp"
#include "elements/PointInertia.hpp"
#include "fem/rotor/RotorCampbell.hpp"
#include "fem/rotor/RotorStability.hpp"
#include "tests/fem/rotor/RotorTestSupport.hpp"

using namespace beamrotor;
using namespace beamrotor::test;

namespace {

struct CrossCoupledJeffcott {
  double m = 20, k = 5e6, c = 800, q = 400;  // kg, N/m, N s/m, N s/m (Q = q Omega)
  double top = 2000;                        // rad/s, end of the bearing table

  double onset() const { return c * std::sqrt(k / m) / q; }  // 1000 rad/s

  /// The least stable mode's log decrement at spin speed `w` (<= top): the root of
  /// m lambda^2 + c lambda + (k - i q w) = 0 with the larger real part (the forward whirl),
  /// -2 pi Re(lambda) / |Im(lambda)|.
  double logDecrement(double w) const {
    const std::complex<double> root =
        (-c + std::sqrt(std::complex<double>(c * c - 4 * m * k, 4 * m * q * w))) / (2 * m);
    return -2 * std::numbers::pi * root.real() / std::abs(root.imag());
  }

  void build(Model& model) const {
    const int n = model.addNode(Eigen::Vector3d::Zero());
    model.add<PointInertia>(n, DofSet{Dof::uy, Dof::uz}, m);
    BearingCoefficients rest = BearingCoefficients::isotropic(k, c), fast = rest;
    fast.kyz = q * top;  // linear interpolation between the rows: Q = q Omega exactly
    fast.kzy = -q * top;
    model.add<Bearing>(n, std::vector<double>{0.0, top},
                       std::vector<BearingCoefficients>{rest, fast});
  }
};

/// The stability half of the API 684 verdict of the CrossCoupledJeffcott rotor over `range`,
/// from 100 rad/s.
OperatingStability jeffcottStability(const OperatingRange& range, double required = 0) {
  const CrossCoupledJeffcott j;
  Model model;
  j.build(model);
  return operatingStability(model, rotorOptions(2), range, 100, required);
}

/// A rigid rotor (E 2e17) on two undamped isotropic bearings of unequal stiffness: a disk
/// off-centre, gyroscopic moments, no damping anywhere.
void buildUndampedRigidRotor(Model& model) {
  auto sec = std::make_shared<Section>(
      Section::circle("shaft", Material::fromEnu("stiff", 2e17, 0.3, 7850), 0.1));
  LineSpec spec;
  spec.dofs = DofSet::lateral();
  spec.segments.push_back({1.0, sec, 4, 0, {BeamTheory::timoshenko, MassModel::consistent, true}});
  spec.points = {{"A", 0.1}, {"B", 0.9}, {"disk", 0.7}};
  buildLine(model, spec);
  model.add<PointInertia>(model.node("disk"), DofSet::lateral(), 30, 0.6, 0.35);
  model.add<Bearing>(model.node("A"), BearingCoefficients::isotropic(1e7));
  model.add<Bearing>(model.node("B"), BearingCoefficients::isotropic(1.3e7));
}

std::vector<double> grid(double top, int steps) {
  std::vector<double> s;
  for (int i = 0; i <= steps; ++i) s.push_back(top * i / steps);
  return s;
}

}  // namespace

TEST_SUITE("rotor stability") {
  TEST_CASE("onset speed of a cross-coupled Jeffcott rotor against c sqrt(k/m) / q") {
    const CrossCoupledJeffcott j;
    Model model;
    j.build(model);
    const RotorOptions options = rotorOptions(2);
    const CampbellResult campbell = solveCampbell(model, grid(j.top, 7), options);
    const auto onset = instabilityOnset(model, campbell, options);
    REQUIRE(onset.has_value());
    // Refined to 1e-10 of the speed; the dense eigensolver's Re(lambda) is good to ~1e-13 of
    // |lambda|, which moves the root by far less. 1e-8 leaves room for both.
    CHECK(onset->speed == doctest::Approx(j.onset()).epsilon(1e-8));
    CHECK(onset->rpm == doctest::Approx(j.onset() * 30 / std::numbers::pi).epsilon(1e-8));
    // It whirls forward at the undamped natural frequency sqrt(k / m).
    CHECK(onset->frequencyHz ==
          doctest::Approx(std::sqrt(j.k / j.m) / (2 * std::numbers::pi)).epsilon(1e-8));
    CHECK(onset->whirl == Whirl::forward);
    // The grid alone would place it only within a 286 rad/s interval; the refinement is cheap.
    CHECK(onset->evaluations < 30);
    // Log decrements on the grid: the forward mode's changes sign across the onset.
    bool stableBefore = true, unstableAfter = false;
    for (std::size_t s = 0; s < campbell.speeds.size(); ++s)
      for (const auto& line : campbell.lines) {
        if (campbell.speeds[s] < j.onset() && line[s].logDecrement < 0) stableBefore = false;
        if (campbell.speeds[s] > j.onset() && line[s].logDecrement < 0) unstableAfter = true;
      }
    CHECK(stableBefore);
    CHECK(unstableAfter);
  }

  TEST_CASE("the least damped mode: the forward whirl at the top speed, against the closed form") {
    // The forward whirl's log decrement falls with the speed (Q = q Omega grows), so over the
    // grid it is least at the top speed, and from speed index 3 on as well; below that, the
    // diagram cut at index 2 is least damped at index 2.
    const CrossCoupledJeffcott j;
    Model model;
    j.build(model);
    const CampbellResult campbell = solveCampbell(model, grid(j.top, 7), rotorOptions(2));
    const auto all = leastDamped(campbell);
    REQUIRE(all.has_value());
    CHECK(all->speed == 7);
    CHECK(campbell.lines[all->line][all->speed].whirl == Whirl::forward);
    // The dense eigensolver's eigenvalues are good to ~1e-13 |lambda|; the decrement, a ratio
    // of their parts, to ~1e-12 relative here (|Re lambda| ~ |Im lambda| / 100).
    CHECK(all->logDecrement == doctest::Approx(j.logDecrement(j.top)).epsilon(1e-9));
    CHECK(all->logDecrement < 0);  // past the onset
    const auto fromThird = leastDamped(campbell, 3);
    REQUIRE(fromThird.has_value());
    CHECK(fromThird->speed == 7);
    CampbellResult low = campbell;
    for (auto& line : low.lines) line.resize(3);
    const auto lowest = leastDamped(low);
    REQUIRE(lowest.has_value());
    CHECK(lowest->speed == 2);
    CHECK(lowest->logDecrement == doctest::Approx(j.logDecrement(2 * j.top / 7)).epsilon(1e-9));

    // Read as the verdict reads: round-off below 1e-9 is 0, a mode that grows without
    // oscillating (-inf) is the least damped of all, and a NaN is passed over.
    CampbellResult table;
    table.speeds = {0, 1};
    table.lines.assign(2, std::vector<RotorMode>(2));
    table.lines[0][0].logDecrement = 0.05;
    table.lines[0][1].logDecrement = -4e-13;  // an undamped mode's round-off
    table.lines[1][0].logDecrement = std::nan("");
    table.lines[1][1].logDecrement = 0.01;
    auto least = leastDamped(table);
    REQUIRE(least.has_value());
    CHECK(least->line == 0);
    CHECK(least->speed == 1);
    CHECK(least->logDecrement == 0);
    table.lines[1][1].logDecrement = -std::numeric_limits<double>::infinity();
    least = leastDamped(table);
    REQUIRE(least.has_value());
    CHECK(least->line == 1);
    CHECK(least->logDecrement == -std::numeric_limits<double>::infinity());
    CHECK_FALSE(leastDamped(table, 2).has_value());  // no speeds left
  }

  TEST_CASE("an undamped rotor never goes unstable, whatever the sign of its round-off") {
    // Issue 42, defect E. Without damping, with symmetric positive definite K and M and a
    // skew gyroscopic matrix, the energy q'M q' / 2 + q'K q / 2 is conserved (its rate is
    // -Omega q'G q' = 0), so no mode grows, and the spectrum's symmetry lambda -> -conj(lambda)
    // lets none decay either: every decrement is exactly 0 (Thomson and Tait's theorem on
    // gyroscopic systems). The eigensolver's round-off gives Re(lambda) of either sign: 1e-16
    // of |lambda| for the rigid modes, 2e-9 for the stiff shaft's bending modes 4800 times
    // further from the shift. Judged on Re(lambda) itself, one such sign once made this
    // rotor "unstable above 97 rpm" (two lines) or above any speed at all.
    Model model;
    buildUndampedRigidRotor(model);
    std::vector<double> speeds;
    for (int i = 0; i <= 10; ++i) speeds.push_back(10 + 299.0 * i);
    for (int modes : {2, 4, 6}) {
      CAPTURE(modes);
      const RotorOptions options = rotorOptions(modes);
      const CampbellResult campbell = solveCampbell(model, speeds, options);
      CHECK_FALSE(instabilityOnset(model, campbell, options).has_value());
      const auto least = leastDamped(campbell);
      REQUIRE(least.has_value());
      CHECK(least->logDecrement == 0);
      CHECK_FALSE(campbell.untracked.has_value());
      // Each mode's round-off band holds the exact 0 its damping ratio stands for.
      double largest = 0;
      for (const auto& line : campbell.lines)
        for (const RotorMode& m : line) {
          CHECK(std::abs(m.dampingRatio) <= m.roundOff);
          largest = std::max(largest, std::abs(m.dampingRatio));
        }
      MESSAGE(modes << " lines: largest |zeta| of the undamped rotor " << largest);
    }
  }

  TEST_CASE("no onset when the cross-coupling stays below the damping's reach") {
    CrossCoupledJeffcott j;
    j.top = 0.9 * j.onset();  // the table ends below the onset and is held beyond
    Model model;
    j.build(model);
    const RotorOptions options = rotorOptions(2);
    const CampbellResult campbell = solveCampbell(model, grid(3 * j.onset(), 6), options);
    CHECK_FALSE(instabilityOnset(model, campbell, options).has_value());
  }

  // The stability half of the API 684 verdict against the same closed form: the forward
  // mode's log decrement falls steadily with the speed (Q = q Omega grows), so over a range it
  // is smallest at the range's top, and the onset is c sqrt(k/m) / q = 1000 rad/s.
  TEST_CASE("API 684 stability: an operating range across the onset fails, naming it") {
    const CrossCoupledJeffcott j;
    const OperatingStability s = jeffcottStability({0.9 * j.onset(), 1.1 * j.onset()});
    CHECK_FALSE(s.pass);
    REQUIRE(s.onset.has_value());
    CHECK(s.onset->speed == doctest::Approx(j.onset()).epsilon(1e-8));  // as the onset test
    // At the range's top, 1100 rad/s, the dense eigensolver's round-off (~1e-13 of |lambda|)
    // is the only error; 1e-9 of the decrement (-0.0251) leaves room for it.
    CHECK(s.speed == doctest::Approx(1.1 * j.onset()).epsilon(1e-12));
    CHECK(s.smallest == doctest::Approx(j.logDecrement(1.1 * j.onset())).epsilon(1e-9));
    CHECK(s.smallest < 0);
    CHECK(s.whirl == Whirl::forward);
  }

  TEST_CASE("API 684 stability: a range below the onset passes at the required decrement") {
    const CrossCoupledJeffcott j;
    const OperatingRange range{0.5 * j.onset(), 0.9 * j.onset()};
    const double top = j.logDecrement(range.maximum);  // 0.0251, the smallest in the range
    const OperatingStability s = jeffcottStability(range);
    CHECK(s.pass);
    CHECK_FALSE(s.onset.has_value());
    CHECK(s.smallest == doctest::Approx(top).epsilon(1e-9));
    // A required log decrement just above what the rotor keeps fails it, just below passes.
    CHECK_FALSE(jeffcottStability(range, top + 1e-4).pass);
    CHECK(jeffcottStability(range, top - 1e-4).pass);
  }

  TEST_CASE("API 684 stability: an onset below the operating range fails it too") {
    const CrossCoupledJeffcott j;
    const OperatingStability s = jeffcottStability({1.2 * j.onset(), 1.5 * j.onset()});
    CHECK_FALSE(s.pass);
    REQUIRE(s.onset.has_value());
    CHECK(s.onset->speed == doctest::Approx(j.onset()).epsilon(1e-8));
    CHECK(s.smallest == doctest::Approx(j.logDecrement(1.5 * j.onset())).epsilon(1e-9));
  }
}

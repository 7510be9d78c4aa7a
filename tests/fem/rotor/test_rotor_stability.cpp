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

  TEST_CASE("no onset when the cross-coupling stays below the damping's reach") {
    CrossCoupledJeffcott j;
    j.top = 0.9 * j.onset();  // the table ends below the onset and is held beyond
    Model model;
    j.build(model);
    const RotorOptions options = rotorOptions(2);
    const CampbellResult campbell = solveCampbell(model, grid(3 * j.onset(), 6), options);
    CHECK_FALSE(instabilityOnset(model, campbell, options).has_value());
  }
}

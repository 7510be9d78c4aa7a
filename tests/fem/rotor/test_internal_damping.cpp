// Internal (rotating) damping of the shaft against the closed forms of a Jeffcott rotor.
//
// A disk m at mid-span of a massless shaft (stiffness k at the disk), a fixed damper c_e at
// the disk and viscous damping in the shaft's material, c_i = beta_i k. In the rotating frame
// the material damping acts on the strain rate, so in fixed coordinates, r = uy + i uz,
//   m r'' + (c_e + c_i) r' + (k - i Omega c_i) r = 0
// (Genta, Dynamics of Rotating Systems, 2005, sec. 6.3; Friswell et al. 2010, sec. 5.4).
// On the stability boundary r = e^{i w t}: the real part gives w^2 = k / m, the imaginary part
// (c_e + c_i) w = Omega c_i: the forward whirl grows above Omega* = omega_n (1 + c_e / c_i),
// whirling at omega_n. Below the critical speed internal damping only damps.
//
// In the FE model the shaft's force is (1 + beta_i (lambda - i Omega)) K_s q for a forward
// whirl (K_s commutes with the quarter turn R of an axisymmetric shaft), a scalar factor on
// K_s, so its condensation onto the disk is k times that factor: the closed form holds to
// round-off (and the shaft's 4e-13 mass ratio).
#include <doctest/doctest.h>

#include <algorithm>
#include <cmath>
#include <complex>
#include <numbers>
#include <vector>

#include "fem/rotor/RotorCampbell.hpp"
#include "fem/rotor/RotorStability.hpp"
#include "fem/rotor/RotorSystem.hpp"
#include "tests/fem/rotor/RotorTestSupport.hpp"

using namespace beamrotor;
using namespace beamrotor::test;

namespace {

struct InternalJeffcott {
  double L = 0.7, D = 0.03, m = 20, E = 2.1e11;  // m, m, kg, Pa
  double ce = 100;       // N s/m, the fixed damper at the disk
  double beta = 2e-4;    // s, the shaft's internal damping

  double k() const { return 48 * E * (std::numbers::pi * std::pow(D, 4) / 64) / std::pow(L, 3); }
  double ci() const { return beta * k(); }
  double omegaN() const { return std::sqrt(k() / m); }
  double onset() const { return omegaN() * (1 + ce / ci()); }

  /// The damped modes at spin speed w in the program's convention (Im lambda >= 0): the roots
  /// of m l^2 + (c_e + c_i) l + k - i w c_i with Im > 0 (forward whirl) and the conjugates of
  /// those with Im < 0 (backward), sorted by frequency.
  std::vector<Complex> modes(double w) const {
    const Complex b = ce + ci(), c(k(), -w * ci());
    const Complex root = std::sqrt(b * b - 4 * m * c);
    std::vector<Complex> out;
    for (Complex l : {(-b + root) / (2 * m), (-b - root) / (2 * m)})
      out.push_back(l.imag() >= 0 ? l : std::conj(l));
    std::sort(out.begin(), out.end(), [](Complex a, Complex b) { return a.imag() < b.imag(); });
    return out;
  }

  int build(Model& model) const {
    return buildJeffcottRotor(model, L, D, m, E, BearingCoefficients::isotropic(0, ce));
  }
  ProportionalDamping damping() const {
    ProportionalDamping d;
    d.internal = beta;
    return d;
  }
};

}  // namespace

TEST_SUITE("rotor internal damping") {
  TEST_CASE("Jeffcott rotor: damped modes against the roots of the closed form") {
    const InternalJeffcott j;
    Model model;
    j.build(model);
    // Below, at and above the critical speed (241.7 rad/s) and past the onset (1.47 omega_n).
    for (double w : {0.0, 150.0, j.omegaN(), 1.2 * j.onset()}) {
      CAPTURE(w);
      const RotorModesResult r = solveRotorModes(model, w, rotorOptions(2, 0, j.damping()));
      REQUIRE(r.modes.size() == 2);
      // Each root of the closed form against the nearest mode (past the onset the two whirls'
      // frequencies differ by 1e-5 only, so their order says nothing): the dense
      // eigensolver's round-off (~1e-13 |lambda|) and the shaft's 4e-13 mass ratio.
      for (const Complex want : j.modes(w)) {
        CAPTURE(want);
        const double error = std::min(std::abs(r.modes[0].eigenvalue - want),
                                      std::abs(r.modes[1].eigenvalue - want));
        CHECK(error < 1e-9 * std::abs(want));
      }
    }
    // Past the onset the forward whirl grows, the backward one decays.
    const RotorModesResult past =
        solveRotorModes(model, 1.2 * j.onset(), rotorOptions(2, 0, j.damping()));
    for (const RotorMode& mode : past.modes)
      CHECK((mode.whirl == Whirl::forward) == (mode.eigenvalue.real() > 0));
  }

  TEST_CASE("Jeffcott rotor: the onset of instability is omega_n (1 + c_e / c_i)") {
    const InternalJeffcott j;
    Model model;
    j.build(model);
    std::vector<double> speeds;
    for (int i = 0; i <= 8; ++i) speeds.push_back(600.0 * i / 8);
    const RotorOptions options = rotorOptions(2, 0, j.damping());
    const CampbellResult campbell = solveCampbell(model, speeds, options);
    const auto onset = instabilityOnset(model, campbell, options);
    REQUIRE(onset.has_value());
    MESSAGE("onset " << onset->speed << " rad/s, closed form " << j.onset() << ", rel. error "
                     << onset->speed / j.onset() - 1);
    // Refined to 1e-10 of the speed (SpeedRoot); the eigenvalues' round-off moves the root by
    // far less. 1e-8 leaves room for both.
    CHECK(onset->speed == doctest::Approx(j.onset()).epsilon(1e-8));
    CHECK(onset->frequencyHz == doctest::Approx(j.omegaN() / (2 * std::numbers::pi)).epsilon(1e-8));
    CHECK(onset->whirl == Whirl::forward);

    // Without the fixed damper the rotor goes unstable right at the critical speed.
    Model bare;
    buildJeffcottRotor(bare, j.L, j.D, j.m, j.E);
    const CampbellResult free = solveCampbell(bare, speeds, options);
    const auto atCritical = instabilityOnset(bare, free, options);
    REQUIRE(atCritical.has_value());
    CHECK(atCritical->speed == doctest::Approx(j.omegaN()).epsilon(1e-8));
  }

  TEST_CASE("the circulatory matrix is skew, the rotating damping symmetric, and both vanish "
            "without internal damping") {
    const InternalJeffcott j;
    Model model;
    j.build(model);
    const RotorSystem with(model, j.damping()), without(model);
    const double w = 300;
    const Eigen::MatrixXd circulatory =
        Eigen::MatrixXd(with.stiffness(w)) - Eigen::MatrixXd(without.stiffness(w));
    const Eigen::MatrixXd rotating =
        Eigen::MatrixXd(with.damping(w)) - Eigen::MatrixXd(without.damping(w));
    const double scale = circulatory.norm();
    REQUIRE(scale > 0);
    // An axisymmetric shaft's K_s commutes with the quarter turn R: K_s R is skew, exactly up
    // to the round-off of the beams' entries.
    CHECK((circulatory + circulatory.transpose()).norm() < 1e-14 * scale);
    CHECK((rotating - rotating.transpose()).norm() < 1e-14 * rotating.norm());
    // Omega beta_i K_s R and beta_i K_s carry the same entries up to the quarter turn: equal norms.
    CHECK(scale == doctest::Approx(w * rotating.norm()).epsilon(1e-12));
    // At rest the stiffness is that without internal damping.
    CHECK((Eigen::MatrixXd(with.stiffness(0)) - Eigen::MatrixXd(without.stiffness(0))).norm() == 0);
  }
}

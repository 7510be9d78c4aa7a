// Whirl of a flexible spinning shaft against closed forms: a uniform shaft simply supported at
// both ends, with the rotary inertia and gyroscopic moments of its cross-sections, as a Rayleigh
// shaft (Euler-Bernoulli elements) and as a Timoshenko shaft. Unlike the rigid rotor's, these
// closed forms depend on how the shaft's distributed gyroscopic matrix varies along an element.
#include <doctest/doctest.h>

#include <algorithm>
#include <cmath>

#include "fem/rotor/RotorCampbell.hpp"
#include "fem/rotor/RotorModes.hpp"
#include "tests/Helpers.hpp"
#include "tests/fem/rotor/RotorTestSupport.hpp"

using namespace beamrotor;
using namespace beamrotor::test;

namespace {

/// A uniform solid steel shaft along x, simply supported (uy = uz = 0) at both ends.
///
/// Equations of motion (Lalanne and Ferraris, Rotordynamics Prediction in Engineering, 1998,
/// ch. 3; Friswell et al., Dynamics of Rotating Machines, 2010, ch. 5), with the lateral
/// displacement r = uy + i uz and the section rotation psi = rz - i ry as complex numbers,
/// spin Omega about +x:
///   rho A r'' = kappa G A (r_x - psi)_x,
///   rho I psi'' - i Omega rho Ip psi' = E I psi_xx + kappa G A (r_x - psi),
/// (' time, _x space derivatives; Ip = 2 I). Simply supported ends (r = 0, E I psi_x = 0) are
/// met by r = U sin(k x), psi = Psi cos(k x) with k = n pi / L, n = 1, 2, ... A whirl
/// e^{i w t} (w > 0 forward, turning with the spin; w < 0 backward, written as +w with the
/// sign of Omega flipped) then needs
///   (kappa G A k^2 - rho A w^2) (E I k^2 + kappa G A - rho I w^2 + s Omega rho Ip w)
///     - (kappa G A k)^2 = 0,                                      s = +1 forward, -1 backward.
/// Without shear (kappa G A -> infinity, the Rayleigh shaft) this is the quadratic
///   (rho A + rho I k^2) w^2 - s rho Ip k^2 Omega w - E I k^4 = 0.
struct WhirlShaft {
  double L = 1.0, D = 0.1;
  std::shared_ptr<const Section> section = steelCircle(D);
  double rho() const { return section->material.rho; }
  double E() const { return section->material.E; }
  double G() const { return section->material.G; }
  double A() const { return kPi * D * D / 4; }
  double I() const { return kPi * std::pow(D, 4) / 64; }
  /// Cowper (1966), solid circle.
  double kappa() const {
    const double nu = section->material.nu;
    return 6 * (1 + nu) / (7 + 6 * nu);
  }

  double rayleigh(int n, double speed, int sense) const {
    const double k = n * kPi / L;
    const double m = rho() * A() + rho() * I() * k * k, g = rho() * 2 * I() * k * k;
    const double K = E() * I() * std::pow(k, 4);
    return (sense * g * speed + std::sqrt(g * g * speed * speed + 4 * m * K)) / (2 * m);
  }

  /// The lowest root of the Timoshenko frequency equation: the equation is positive at w = 0
  /// (kappa G A E I k^4) and -(kappa G A k)^2 < 0 where its first factor vanishes, so the
  /// bending root lies between; bisection to round-off.
  double timoshenko(int n, double speed, int sense) const {
    const double k = n * kPi / L, kGA = kappa() * G() * A();
    const double rhoA = rho() * A(), rhoI = rho() * I(), rhoIp = 2 * rhoI;
    auto f = [&](double w) {
      return (kGA * k * k - rhoA * w * w) *
                 (E() * I() * k * k + kGA - rhoI * w * w + sense * speed * rhoIp * w) -
             kGA * kGA * k * k;
    };
    double lo = 0, hi = std::sqrt(kGA * k * k / rhoA);
    for (int i = 0; i < 200 && hi - lo > 1e-15 * hi; ++i) {
      const double mid = (lo + hi) / 2;
      (f(mid) > 0 ? lo : hi) = mid;
    }
    return (lo + hi) / 2;
  }

  double closedForm(BeamTheory theory, int n, double speed, int sense) const {
    return theory == BeamTheory::timoshenko ? timoshenko(n, speed, sense)
                                            : rayleigh(n, speed, sense);
  }

  void build(Model& model, int elements, BeamTheory theory) const {
    const Line line = uniformBeam(model, L, section, elements, DofSet::lateral(),
                                  {theory, MassModel::consistent, true});
    for (int node : {line.nodes.front(), line.nodes.back()})
      model.addSupport({"end " + std::to_string(node), node, {{Dof::uy, 0}, {Dof::uz, 0}}});
  }
};

/// Largest relative error of the three lowest forward and backward whirl frequencies at
/// `speed`, each mode matched to the closed form by its whirl sense.
double worstWhirlError(const WhirlShaft& shaft, BeamTheory theory, int elements, double speed) {
  Model model;
  shaft.build(model, elements, theory);
  const RotorModesResult r = solveRotorModes(model, speed, rotorOptions(6));
  REQUIRE(r.modes.size() == 6);
  std::vector<double> forward, backward;
  for (const RotorMode& m : r.modes) {
    CHECK(m.whirl != Whirl::planar);
    (m.whirl == Whirl::forward ? forward : backward).push_back(m.dampedFrequency);
    // Undamped: the eigenvalues lie on the imaginary axis up to round-off.
    CHECK(std::abs(m.eigenvalue.real()) < 1e-9 * m.naturalFrequency);
  }
  REQUIRE(forward.size() == 3);
  REQUIRE(backward.size() == 3);
  std::sort(forward.begin(), forward.end());
  std::sort(backward.begin(), backward.end());
  double worst = 0;
  for (int n = 1; n <= 3; ++n) {
    worst = std::max(worst, relError(forward[n - 1], shaft.closedForm(theory, n, speed, +1)));
    worst = std::max(worst, relError(backward[n - 1], shaft.closedForm(theory, n, speed, -1)));
  }
  return worst;
}

}  // namespace

TEST_SUITE("shaft whirl") {
  TEST_CASE("closed forms: the Timoshenko equation tends to the Rayleigh one as shear stiffens") {
    // Guards the references themselves: with G a million times steel's the shear terms vanish.
    WhirlShaft stiff;
    stiff.section = std::make_shared<Section>(
        Section::circle("shaft", Material{"stiff", 200e9, 0.3, 76.9e9 * 1e6, 7850}, stiff.D));
    for (int n : {1, 3})
      for (double speed : {0.0, 5000.0})
        for (int sense : {+1, -1})
          CHECK(relError(stiff.timoshenko(n, speed, sense), stiff.rayleigh(n, speed, sense)) <
                1e-5);
  }

  TEST_CASE("simply supported shaft: forward and backward whirl against the closed forms") {
    // L / D = 10, so rotary inertia and gyroscopics matter: at 6000 rad/s the forward and
    // backward whirl of mode 1 (1242 rad/s at rest as a Rayleigh shaft) lie 6 % apart, and
    // shear lowers mode 3 by 6.6 %. Worst error over the three lowest forward and backward
    // frequencies, measured at 1000, 3000 and 6000 rad/s (8 / 16 / 32 / 64 elements):
    //   Rayleigh (Hermite elements): 1.3e-3, 8.5e-5, 5.4e-6, 3.4e-7: order 3.99 (16 -> 32);
    //   Timoshenko (interdependent interpolation): 8.8e-3, 2.1e-3, 5.0e-4, 1.3e-4: order 2.02,
    //   the rate the symmetric modal test finds for this element once Phi >> 1.
    // Asked at 16 and 32 elements: the order within 0.05 of 4 (or 2) and the error at 32
    // within 20 % of the measured one.
    const WhirlShaft shaft;
    for (BeamTheory theory : {BeamTheory::eulerBernoulli, BeamTheory::timoshenko})
      for (double speed : {1000.0, 3000.0, 6000.0}) {
        const bool rayleigh = theory == BeamTheory::eulerBernoulli;
        CAPTURE(rayleigh);
        CAPTURE(speed);
        const double e16 = worstWhirlError(shaft, theory, 16, speed);
        const double e32 = worstWhirlError(shaft, theory, 32, speed);
        CAPTURE(e16);
        CAPTURE(e32);
        CHECK(e32 < (rayleigh ? 6.5e-6 : 6e-4));
        CHECK(std::abs(std::log2(e16 / e32) - (rayleigh ? 4 : 2)) < 0.05);
      }
  }

  TEST_CASE("Campbell sweep: candidates end at the spectrum's widest gap, lines as the closed form") {
    // 8 lines: modes n = 1..4 of the Rayleigh shaft, each a forward and backward whirl. The
    // first speed computes 8 + 4 candidates, n = 1..6 each twice at rest (the closed form
    // there: 1242, 4921, 10910, 19011, 28981, 40558 rad/s); the later speeds keep 10 or 11.
    // After 11 the distance to the shift (0) grows by 1 (n = 6's double), after 10 by
    // 40558 / 28981 = 1.40: the count is 10, and ARPACK's boundary falls in that gap.
    const WhirlShaft shaft;
    Model model;
    shaft.build(model, 32, BeamTheory::eulerBernoulli);
    const RotorModesResult atRest = solveRotorModes(model, 0, rotorOptions(12));
    REQUIRE(atRest.modes.size() == 12);
    CHECK(candidatesAtGap(atRest.modes, 8, 0) == 10);
    // With 10 lines no count lies between 10 + 2 and the 12 modes computed: all 12 stay.
    CHECK(candidatesAtGap(atRest.modes, 10, 0) == 12);

    // Every line at every speed against the closed form. Tolerance: the worst error of modes
    // 1..3 at 32 elements measured 5.4e-6 (test above); mode 4 (n^4 larger h^4 term) 1.7e-5.
    std::vector<double> speeds;
    for (int s = 0; s <= 6; ++s) speeds.push_back(1000.0 * s);
    const CampbellResult c = solveCampbell(model, speeds, rotorOptions(8));
    REQUIRE(c.lines.size() == 8);
    double worst = 0, worstSecond = 0;
    for (int l = 0; l < 8; ++l)
      for (std::size_t s = 0; s < speeds.size(); ++s) {
        const RotorMode& m = c.lines[l][s];
        CAPTURE(l);
        CAPTURE(s);
        const int sense = m.whirl == Whirl::backward ? -1 : +1;
        CHECK((s == 0 || m.whirl != Whirl::planar));
        worst = std::max(worst, relError(m.dampedFrequency,
                                         shaft.rayleigh(l / 2 + 1, speeds[s], sense)));
        // Second method: the same eigenvalue among 12 modes solved alone at this speed (a
        // cold start and the full margin). ARPACK's tol 1e-13 on nu = 1/lambda: measured 3e-14.
        const RotorModesResult alone = solveRotorModes(model, speeds[s], rotorOptions(12));
        double nearest = 1;
        for (const RotorMode& a : alone.modes)
          nearest = std::min(nearest, std::abs(a.eigenvalue - m.eigenvalue) / std::abs(m.eigenvalue));
        worstSecond = std::max(worstSecond, nearest);
      }
    CHECK(worst < 2e-5);
    CHECK(worstSecond < 1e-11);
    MESSAGE("Campbell of the Rayleigh shaft: closed form " << worst << ", second method "
                                                           << worstSecond);
  }
}

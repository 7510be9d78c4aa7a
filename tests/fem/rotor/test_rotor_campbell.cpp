// Campbell diagrams (mode tracking, critical speeds) and unbalance response against closed
// forms: the rigid rotor of problems/scenes/README.md section 2 and the CampbellJeffcott rotor.
#include <doctest/doctest.h>

#include <cmath>
#include <complex>
#include <numbers>

#include "elements/Bearing.hpp"
#include "elements/PointInertia.hpp"
#include "fem/rotor/CriticalSpeedRefinement.hpp"
#include "fem/rotor/RotorCampbell.hpp"
#include "fem/rotor/RotorModes.hpp"
#include "fem/rotor/RotorUnbalance.hpp"
#include "tests/Helpers.hpp"
#include "tests/fem/rotor/RotorTestSupport.hpp"

using namespace beamrotor;
using namespace beamrotor::test;

namespace {

/// Rigid rotor on two isotropic bearings with b = 0 (see test_rotor_modes.cpp for the
/// closed forms): a very stiff shaft and an off-centre disk.
struct CampbellRigidRotor {
  double L = 1.0, D = 0.1, E = 2e17, rho = 7850;
  double xd = 0.7, md = 30, Jpd = 0.6, Jdd = 0.35;
  double xa = 0.1, xb = 0.9, C1 = 1e7;
  double A() const { return kPi * D * D / 4; }
  double I() const { return kPi * std::pow(D, 4) / 64; }
  double ms() const { return rho * A() * L; }
  double m() const { return ms() + md; }
  double xG() const { return (ms() * L / 2 + md * xd) / m(); }
  double Jp() const { return rho * 2 * I() * L + Jpd; }
  double Jd() const {
    return ms() * L * L / 12 + rho * I() * L + ms() * std::pow(L / 2 - xG(), 2) + Jdd +
           md * std::pow(xd - xG(), 2);
  }
  double C2() const { return C1 * (xG() - xa) / (xb - xG()); }
  double kPhi() const { return C1 * std::pow(xG() - xa, 2) + C2() * std::pow(xb - xG(), 2); }
  double bounce() const { return std::sqrt((C1 + C2()) / m()); }
  double whirl(double W, int sense) const {  // sense +1 forward, -1 backward
    return (sense * Jp() * W + std::sqrt(std::pow(Jp() * W, 2) + 4 * Jd() * kPhi())) / (2 * Jd());
  }
  void build(Model& model) const {
    auto sec = std::make_shared<Section>(
        Section::circle("shaft", Material::fromEnu("stiff", E, 0.3, rho), D));
    LineSpec spec;
    spec.dofs = DofSet::lateral();
    spec.segments.push_back({L, sec, 4, 0, {BeamTheory::timoshenko, MassModel::consistent, true}});
    spec.points = {{"A", xa}, {"B", xb}, {"disk", xd}};
    buildLine(model, spec);
    model.add<PointInertia>(model.node("disk"), DofSet::lateral(), md, Jpd, Jdd);
    model.add<Bearing>(model.node("A"), BearingCoefficients::isotropic(C1));
    model.add<Bearing>(model.node("B"), BearingCoefficients::isotropic(C2()));
  }
};

std::vector<double> linspace(double a, double b, int n) {
  std::vector<double> v(n);
  for (int i = 0; i < n; ++i) v[i] = a + (b - a) * i / (n - 1);
  return v;
}

/// CampbellJeffcott rotor: a massless Euler-Bernoulli shaft (density 1e-12 of steel's: its mass is
/// 4e-13 of the disk's), simply supported, with a point mass at mid-span. Hermite elements are
/// exact for a point load, so the mid-span stiffness is exactly 48 E I / L^3.
struct CampbellJeffcott {
  double L = 0.8, D = 0.025, m = 8, E = 2.1e11;
  double I() const { return kPi * std::pow(D, 4) / 64; }
  double k() const { return 48 * E * I() / std::pow(L, 3); }
  double wn() const { return std::sqrt(k() / m); }
  int build(Model& model, double c = 0) const {
    if (c == 0) return test::buildJeffcottRotor(model, L, D, m, E);
    return test::buildJeffcottRotor(model, L, D, m, E, BearingCoefficients{0, 0, 0, 0, c, 0, 0, c});
  }
};

}  // namespace

TEST_SUITE("rotor campbell") {
  TEST_CASE("MAC table: |a^H b|^2 / (|a|^2 |b|^2) of small complex vectors, worked by hand") {
    const Complex i(0, 1);
    Eigen::MatrixXcd a(3, 2), b(3, 4);
    a.col(0) << 1, 0, 0;
    a.col(1) << 1, i, 0;
    b.col(0) << 2.0 * i, 0, 0;  // a0 times a complex scale
    b.col(1) << 1, -i, 0;       // a1^H b1 = 1 + (-i)(-i) = 0
    b.col(2) << 0, 0, 0;        // no shape: 0, not 0 / 0
    b.col(3) << 1, 1, 1;
    // Rows a0, a1; by hand: a0^H b = (2i, 1, 0, 1), a1^H b = (2i, 0, 0, 1 - i); |a|^2 = 1, 2;
    // |b|^2 = 4, 2, 0, 3.
    const double expected[2][4] = {{1, 0.5, 0, 1.0 / 3}, {0.5, 0, 0, 1.0 / 3}};
    const Eigen::MatrixXd table = macTable(a, b);
    REQUIRE(table.rows() == 2);
    REQUIRE(table.cols() == 4);
    for (int k = 0; k < 2; ++k)
      for (int l = 0; l < 4; ++l) {
        CAPTURE(k);
        CAPTURE(l);
        // A few roundings of numbers of size 1.
        CHECK(table(k, l) == doctest::Approx(expected[k][l]).epsilon(1e-15));
        CHECK(mac(a.col(k), b.col(l)) == table(k, l));
      }
  }

  TEST_CASE("rigid rotor: lines keep their identity through crossings (MAC tracking)") {
    const CampbellRigidRotor r;
    Model model;
    r.build(model);
    // The backward conical branch falls through the (speed-independent) bounce frequency at
    // W = (k_phi - Jd w^2) / (Jp w), w = bounce: sorting by frequency would swap the lines
    // there. Sweep well past it.
    const double w = r.bounce(), crossing = (r.kPhi() - r.Jd() * w * w) / (r.Jp() * w);
    const std::vector<double> speeds = linspace(0, 1.6 * crossing, 41);
    const CampbellResult c = solveCampbell(model, speeds, rotorOptions(4));
    REQUIRE(c.lines.size() == 4);
    // Each line must stay on one branch of the closed form over the whole sweep.
    int bounceLines = 0, forwardLines = 0, backwardLines = 0;
    for (int l = 0; l < 4; ++l) {
      const double wEnd = c.lines[l].back().dampedFrequency;
      const double W = speeds.back();
      const int branch = relError(wEnd, r.bounce()) < 1e-6       ? 0
                         : relError(wEnd, r.whirl(W, +1)) < 1e-6 ? 1
                         : relError(wEnd, r.whirl(W, -1)) < 1e-6 ? -1
                                                                 : 9;
      REQUIRE(branch != 9);
      (branch == 0 ? bounceLines : branch == 1 ? forwardLines : backwardLines)++;
      for (std::size_t s = 0; s < speeds.size(); ++s) {
        const double ref = branch == 0 ? r.bounce() : r.whirl(speeds[s], branch);
        CAPTURE(l);
        CAPTURE(speeds[s]);
        CHECK(relError(c.lines[l][s].dampedFrequency, ref) < 1e-6);
        // At rest the conical pair is a double eigenvalue (any basis), so the first step may
        // correlate only 0.5; after that the conical lines correlate well from step to step:
        // a speed landing within ~1e-7 of the crossing (in frequency) sees the residual
        // coupling of the 'rigid' shaft (flexibility ~1e-7) mix the backward conical and
        // bounce modes (measured: MAC 0.945 at 5989 rad/s, 2.4e-7 from the crossing), while
        // their frequencies stay within 1e-6 of the closed form. The bounce pair stays double
        // at every speed (a pure translation feels no gyroscopic moment), so its basis, and
        // its MAC, is arbitrary.
        if (s >= 2 && branch != 0) CHECK(c.mac[l][s] > 0.9);
      }
      if (branch != 0)
        CHECK(c.lines[l].back().whirl == (branch == 1 ? Whirl::forward : Whirl::backward));
    }
    CHECK(bounceLines == 2);
    CHECK(forwardLines == 1);
    CHECK(backwardLines == 1);
  }

  TEST_CASE("rigid rotor at rest: the bounce pair numbered backward, then forward") {
    // At rest the bounce and the conical mode are each double (the two planes). FORMAT.md's
    // rule (fem/rotor/DegenerateModes.hpp): a repeated pair in the basis of circular orbits,
    // the backward one first. Verified here for the bounce pair; this rotor's conical pair at
    // rest comes out as two straight-line orbits (measured), so only its frequencies are
    // checked, and FORMAT.md says so. Closed forms: bounce sqrt((C1+C2)/m), conical
    // sqrt(k_phi / Jd).
    const CampbellRigidRotor r;
    Model model;
    r.build(model);
    const RotorModesResult modes = solveRotorModes(model, 0, rotorOptions(4));
    REQUIRE(modes.modes.size() == 4);
    const double conical = std::sqrt(r.kPhi() / r.Jd());
    REQUIRE(r.bounce() < conical);
    for (int pair = 0; pair < 2; ++pair) {
      CAPTURE(pair);
      const double reference = pair == 0 ? r.bounce() : conical;
      for (int k = 0; k < 2; ++k) {
        const RotorMode& m = modes.modes[std::size_t(2 * pair + k)];
        // The 4-element stiff shaft (E 2e17) is rigid to ~1e-8 of the frequencies.
        CHECK(relError(m.dampedFrequency, reference) < 1e-6);
        if (pair == 0) CHECK(m.whirl == (k == 0 ? Whirl::backward : Whirl::forward));
      }
    }
  }

  TEST_CASE("rigid rotor: critical speeds where the lines meet 1x, converging as h^2") {
    const CampbellRigidRotor r;
    Model model;
    r.build(model);
    // Closed forms of omega(W) = W: bounce sqrt((C1+C2)/m) (twice, y and z); conical
    // Jd W^2 -+ Jp W^2 = k_phi, i.e. sqrt(k_phi / (Jd - Jp)) forward, sqrt(k_phi / (Jd + Jp))
    // backward.
    const double bounce = r.bounce();
    const double fwd = std::sqrt(r.kPhi() / (r.Jd() - r.Jp()));
    const double bwd = std::sqrt(r.kPhi() / (r.Jd() + r.Jp()));
    double previous = 0;
    for (int n : {21, 41}) {
      const CampbellResult c = solveCampbell(model, linspace(0, 2000, n), rotorOptions(4));
      const std::vector<CriticalSpeed> crit = criticalSpeeds(c);
      REQUIRE(crit.size() == 4);
      // Ascending (for these numbers): bounce twice, backward conical, forward conical.
      REQUIRE(bounce < bwd);
      REQUIRE(bwd < fwd);
      CHECK(crit[2].whirl == Whirl::backward);
      CHECK(crit[3].whirl == Whirl::forward);
      // The bounce lines are flat, so linear interpolation is exact for them.
      CHECK(relError(crit[0].speed, bounce) < 1e-7);
      CHECK(relError(crit[1].speed, bounce) < 1e-7);
      const double err = std::max(relError(crit[2].speed, bwd), relError(crit[3].speed, fwd));
      MESSAGE(n << " speeds: critical speeds " << crit[0].speed << ", " << crit[2].speed << ", "
                << crit[3].speed << " rad/s; conical interpolation error " << err);
      // Interpolating a smooth curve linearly errs by O(h^2), ~h^2 |f''| / (8 |f'|) with
      // f = omega(W) - W: measured 5.0e-6 (h = 100 rad/s) and 1.5e-6 (h = 50), ratio 3.3 (the
      // two bracketing points sit differently on the curve at the two step sizes).
      CHECK(err < (n == 21 ? 1e-5 : 3e-6));
      if (previous > 0) CHECK(previous / err > 3);
      previous = err;
    }
  }

  TEST_CASE("rigid rotor: critical speeds refined on the speed, whatever the sweep's step") {
    // Issue 42, defect D: interpolated between sweep speeds, a crossing errs as the step
    // squared (the test above); refined on the speed (regula falsi on omega_d(W) - W of the
    // line followed into its interval) it meets the closed forms of the case above to the
    // stiff shaft's residual flexibility, on a 7-speed sweep as on a 41-speed one.
    const CampbellRigidRotor r;
    Model model;
    r.build(model);
    const double fwd = std::sqrt(r.kPhi() / (r.Jd() - r.Jp()));
    const double bwd = std::sqrt(r.kPhi() / (r.Jd() + r.Jp()));
    std::vector<CriticalSpeed> coarse;
    for (int n : {7, 41}) {
      CAPTURE(n);
      const CampbellResult c = solveCampbell(model, linspace(0, 2000, n), rotorOptions(4));
      const std::vector<CriticalSpeed> interpolated = criticalSpeeds(c);
      const std::vector<CriticalSpeed> refined = refinedCriticalSpeeds(model, c, rotorOptions(4));
      REQUIRE(refined.size() == 4);
      REQUIRE(interpolated.size() == 4);
      // Ascending; the bounce pair crosses at one speed, its forward whirl (the one an
      // unbalance drives) first.
      CHECK(refined[0].whirl == Whirl::forward);
      CHECK(refined[1].whirl == Whirl::backward);
      CHECK(refined[2].whirl == Whirl::backward);
      CHECK(refined[3].whirl == Whirl::forward);
      const double references[] = {r.bounce(), r.bounce(), bwd, fwd};
      for (std::size_t k = 0; k < 4; ++k) {
        CAPTURE(k);
        // Measured 3.9e-8 for the bounce pair, 6.5e-9 for the conical crossings: the 4-element
        // stiff shaft's flexibility (E 2e17), not the step; 1e-7 leaves room for both.
        CHECK(relError(refined[k].speed, references[k]) < 1e-7);
        CHECK(relError(refined[k].rpm, references[k] * 30 / kPi) < 1e-7);
        CHECK(relError(refined[k].frequencyHz, references[k] / (2 * kPi)) < 1e-7);
        // Undamped: the line's own damping ratio there, zero up to its round-off.
        CHECK(std::abs(refined[k].dampingRatio) < 1e-12);
      }
      const double interpolationError = relError(interpolated[3].speed, fwd);
      MESSAGE(n << " speeds: forward conical critical speed interpolated to "
                << interpolationError << ", refined to " << relError(refined[3].speed, fwd));
      if (n == 7) {
        // The coarse sweep's interpolation: measured 6.6e-5, four orders above.
        CHECK(interpolationError > 1e-5);
        coarse = refined;
      } else {
        // The same roots from brackets of another sweep: 1e-10 of the speed each (the
        // refinement's tolerance) and the eigensolver's round-off.
        for (std::size_t k = 0; k < 4; ++k) CHECK(relError(refined[k].speed, coarse[k].speed) < 1e-9);
      }
    }
  }

  TEST_CASE("CampbellJeffcott rotor: critical speed sqrt(k/m), k = 48 E I / L^3") {
    const CampbellJeffcott j;
    Model model;
    j.build(model);
    const CampbellResult c = solveCampbell(model, linspace(0, 2 * j.wn(), 11), rotorOptions(2));
    const std::vector<CriticalSpeed> crit = criticalSpeeds(c);
    REQUIRE(crit.size() == 2);  // the y and z bending modes, forward and backward whirl
    MESSAGE("CampbellJeffcott critical speed error " << relError(crit[0].speed, j.wn()) << ", "
                                                     << relError(crit[1].speed, j.wn()));
    for (const CriticalSpeed& cs : crit) {
      // The line is flat (a disk at mid-span does not tilt): only the shaft's 4e-13 relative
      // mass and round-off remain (measured 1.1e-13).
      CHECK(relError(cs.speed, j.wn()) < 1e-9);
      CHECK(relError(cs.rpm, j.wn() * 60 / (2 * kPi)) < 1e-9);
    }
  }

  TEST_CASE("CampbellJeffcott rotor: unbalance response m e W^2 / (k - m W^2 + i c W)") {
    const CampbellJeffcott j;
    const double me = 2e-4;  // kg m
    double worst = 0;
    for (double c : {0.0, 150.0}) {
      CAPTURE(c);
      Model model;
      const int disk = j.build(model, c);
      // 24 speeds: none lands on w_n, where the undamped system is singular.
      std::vector<double> speeds = linspace(0.1 * j.wn(), 2.5 * j.wn(), 24);
      if (c > 0) speeds.push_back(j.wn());  // at resonance: amplitude m e w_n / c, lag 90 deg
      for (double phase : {0.0, 0.8}) {
        const UnbalanceResult res = solveUnbalance(model, {{disk, me, phase}}, speeds, {disk});
        REQUIRE(res.orbits.size() == 1);
        for (std::size_t s = 0; s < speeds.size(); ++s) {
          const double W = speeds[s];
          const Complex expected =
              me * W * W / Complex(j.k() - j.m * W * W, c * W) * std::polar(1.0, phase);
          const Orbit& o = res.orbits[0][s];
          worst = std::max(worst, std::abs(o.uy - expected) / std::abs(expected));
          CAPTURE(W);
          CHECK(std::abs(o.uy - expected) < 1e-9 * std::abs(expected));
          // A rotating force on an isotropic rotor gives a circular forward orbit.
          CHECK(std::abs(o.uz - Complex(0, -1) * expected) < 1e-9 * std::abs(expected));
          CHECK(o.whirlRatio() == doctest::Approx(1).epsilon(1e-9));
          CHECK(relError(o.major(), std::abs(expected)) < 1e-9);
        }
        if (c > 0) {
          const Orbit& o = res.orbits[0].back();
          CHECK(relError(std::abs(o.uy), me * j.wn() / c) < 1e-9);
          CHECK(std::arg(o.uy) - phase == doctest::Approx(-kPi / 2).epsilon(1e-9));
        }
      }
    }
    MESSAGE("CampbellJeffcott unbalance response: largest relative error " << worst);
  }

  TEST_CASE("line identity: the same lines whatever eigensolves ran before") {
    const CampbellRigidRotor r;
    Model model;
    r.build(model);  // 20 free dofs, 40 states: the Arnoldi path (ARPACK)
    const std::vector<double> speeds = linspace(0, 3000, 13);
    const CampbellResult first = solveCampbell(model, speeds, rotorOptions(4));
    // An unrelated analysis in between: another rotor's modes, through ARPACK too (ARPACK's
    // own random start vector would continue from here).
    const CampbellJeffcott j;
    Model other;
    j.build(other);
    REQUIRE(solveRotorModes(other, 300, rotorOptions(4)).modes.size() == 4);
    const CampbellResult second = solveCampbell(model, speeds, rotorOptions(4));
    // The same arithmetic in the same order: equal to the last bit, line by line.
    for (int l = 0; l < 4; ++l)
      for (std::size_t s = 0; s < speeds.size(); ++s) {
        CAPTURE(l);
        CAPTURE(s);
        CHECK(first.lines[l][s].eigenvalue == second.lines[l][s].eigenvalue);
        CHECK(first.lines[l][s].whirlRatio == second.lines[l][s].whirlRatio);
        CHECK(first.mac[l][s] == second.mac[l][s]);
      }
  }

  TEST_CASE("a 200-element rotor: 50-speed Campbell diagram and unbalance sweep stay sparse") {
    Model model;
    const Line line = uniformBeam(model, 2.0, steelCircle(0.08), 200, DofSet::lateral(),
                                  {BeamTheory::timoshenko, MassModel::consistent, true});
    for (int at : {50, 100, 150})
      model.add<PointInertia>(line.nodes[at], DofSet::lateral(), 40, 0.8, 0.45);
    BearingCoefficients slow{2e8, 1e7, -1e7, 3e8, 2e3, 0, 0, 3e3};
    BearingCoefficients fast{3e8, 4e7, -4e7, 4e8, 1.5e3, 0, 0, 2e3};
    for (int at : {10, 190})
      model.add<Bearing>(line.nodes[at], std::vector<double>{0, 1000},
                         std::vector<BearingCoefficients>{slow, fast});
    const CampbellResult c = solveCampbell(model, linspace(0, 1000, 50), rotorOptions(6));
    CHECK(c.symbolicAnalyses == 1);
    CHECK(c.size.freeDofs == 804);
    // Speed is measured by `make bench` (bench --kind rotor), never asserted here: a loaded
    // test machine would fail a timed check with nothing wrong.

    const std::vector<double> speeds = linspace(10, 1000, 50);
    const UnbalanceResult u =
        solveUnbalance(model, {{line.nodes[100], 1e-4, 0}}, speeds, {line.nodes[50]});
    CHECK(u.symbolicAnalyses == 1);
  }
}

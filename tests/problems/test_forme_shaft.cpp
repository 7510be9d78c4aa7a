// Spring-mounted forme shaft (problems/scenes/README.md section 2): the two-dof closed form, its
// decoupled case, the FE model's rigid limit, how much real shaft flexibility lowers the
// frequencies, and the rotor extension (conical whirl of the spinning shaft).
#include <doctest/doctest.h>

#include <algorithm>
#include <cmath>
#include <numbers>

#include "fem/modal/Modal.hpp"
#include "fem/rotor/RotorModes.hpp"
#include "problems/scenes/FormeShaft.hpp"
#include "tests/Helpers.hpp"

using namespace beamrotor;
using namespace beamrotor::test;

namespace {

// Closed-form arithmetic on O(1)-conditioned formulas: round-off only.
constexpr double kFormeRoundOff = 1e-12;

/// Rigid-body properties of the default design from section integrals (independent of the
/// FE matrices): each prismatic piece contributes m, m L^2/12 + rho I L about its centre
/// (the second term is the sections' rotary inertia) and rho Ip L about the axis.
RigidBodyProperties sectionIntegrals(const FormeShaftDesign& d) {
  struct Piece {
    double x0, L, D, bore;
  };
  const Piece pieces[] = {
      {0, d.operatorJournal, d.journalDiameter, 0},
      {d.operatorJournal, d.barrelLength, d.barrelDiameter, d.barrelBore},
      {d.operatorJournal + d.barrelLength, d.driveJournal, d.journalDiameter, 0}};
  double m = d.gearMass, S = d.gearMass * (d.operatorJournal + d.barrelLength + d.gearInset);
  for (const Piece& p : pieces) {
    const double A = kPi / 4 * (p.D * p.D - p.bore * p.bore);
    m += d.rho * A * p.L;
    S += d.rho * A * p.L * (p.x0 + p.L / 2);
  }
  RigidBodyProperties r;
  r.m = m;
  r.xG = S / m;
  const double xGear = d.operatorJournal + d.barrelLength + d.gearInset;
  r.J = d.gearJd + d.gearMass * std::pow(xGear - r.xG, 2);
  r.Jp = d.gearJp;
  for (const Piece& p : pieces) {
    const double A = kPi / 4 * (p.D * p.D - p.bore * p.bore);
    const double I = kPi / 64 * (std::pow(p.D, 4) - std::pow(p.bore, 4));
    const double mp = d.rho * A * p.L;
    r.J += mp * p.L * p.L / 12 + d.rho * I * p.L + mp * std::pow(p.x0 + p.L / 2 - r.xG, 2);
    r.Jp += d.rho * 2 * I * p.L;
  }
  return r;
}

/// The two lowest bending frequencies (rad/s) of a planar model.
std::array<double, 2> lowestTwo(const Model& model) {
  const ModalResult r = solveModes(model, {2, 0});
  REQUIRE(r.modes.size() == 2);
  return {std::sqrt(r.modes[0].eigenvalue), std::sqrt(r.modes[1].eigenvalue)};
}

FormeShaftDesign stiff(FormeShaftDesign d) {
  // Rigid limit: E up by 1e6 and a coarse mesh (one element per piece between stations), so
  // the shaft's element stiffness, and the round-off it brings to the soft spring modes
  // (eps k_element / C), stays small; rigid-body inertia is exact on any mesh.
  d.E = 2e17;
  d.elementSize = 1.0;
  return d;
}

}  // namespace

TEST_SUITE("forme shaft") {
  TEST_CASE("closed form: both equations hold, n_i = b / (k_i^2 - a), loads balance") {
    const FormeShaftDesign design;
    const FormeShaftRigid s =
        rigidModel(sectionIntegrals(design), 0.08, 1.29, design.C1, design.C2);
    REQUIRE(std::abs(s.b()) > 0);
    const auto modes = formeShaftModes(s);
    const double a = s.a(), b = s.b(), d = s.d(), r2 = s.rho2();
    CHECK(modes[0].k < modes[1].k);
    CHECK(relError(modes[0].k * modes[0].k + modes[1].k * modes[1].k, a + d / r2) < kFormeRoundOff);
    CHECK(relError(std::pow(modes[0].k * modes[1].k, 2), (a * d - b * b) / r2) < kFormeRoundOff);
    for (const FormeShaftMode& mode : modes) {
      const double k2 = mode.k * mode.k;
      CHECK(mode.kind == FormeModeKind::coupled);
      // The paper's two equations of motion, divided by m.
      CHECK(std::abs((a - k2) * mode.z + b * mode.phi) <=
            kFormeRoundOff * ((a + k2) * std::abs(mode.z) + std::abs(b * mode.phi)));
      CHECK(std::abs(b * mode.z + (d - r2 * k2) * mode.phi) <=
            kFormeRoundOff * (std::abs(b * mode.z) + (d + r2 * k2) * std::abs(mode.phi)));
      CHECK(relError(mode.n, b / (k2 - a)) < 1e-10);
      CHECK(relError(mode.z * mode.z + r2 * mode.phi * mode.phi, 1.0) < kFormeRoundOff);
      // Dynamic equilibrium of the shaft: inertia against the two spring loads.
      const double scale = std::abs(mode.FA) + std::abs(mode.FB);
      CHECK(std::abs(mode.inertiaForce + mode.FA + mode.FB) <= kFormeRoundOff * scale);
      CHECK(std::abs(mode.inertiaMoment + s.l2 * mode.FB - s.l1 * mode.FA) <=
            kFormeRoundOff * scale * (s.l1 + s.l2));
    }
    // Modes are orthogonal in the mass: m z1 z2 + J phi1 phi2 = 0.
    CHECK(std::abs(modes[0].z * modes[1].z + r2 * modes[0].phi * modes[1].phi) < kFormeRoundOff);
    MESSAGE("design: k1 = " << modes[0].k << " rad/s (n1 = " << modes[0].n
                            << " m/rad, FA = " << modes[0].FA << " N, FB = " << modes[0].FB
                            << " N), k2 = " << modes[1].k << " rad/s (n2 = " << modes[1].n
                            << " m/rad, FA = " << modes[1].FA << " N, FB = " << modes[1].FB
                            << " N), per unit z^2 + rho^2 phi^2");
  }

  TEST_CASE("b = 0: n_i is 0/0 in the paper; here pure bounce (n = inf) and rocking (n = 0)") {
    // C1 l1 = C2 l2 exactly (1e8 * 0.5 = 2e8 * 0.25).
    FormeShaftRigid s{400, 0, 1e8, 2e8, 0.5, 0.25};
    for (double rho2 : {0.01, 0.5}) {  // rocking above the bounce, then below it
      CAPTURE(rho2);
      s.J = s.m * rho2;
      REQUIRE(s.b() == 0);
      const auto modes = formeShaftModes(s);
      const double bounce = std::sqrt(s.a()), rocking = std::sqrt(s.d() / rho2);
      const int ib = bounce < rocking ? 0 : 1;
      CHECK(modes[ib].kind == FormeModeKind::bounce);
      CHECK(modes[1 - ib].kind == FormeModeKind::rocking);
      CHECK(relError(modes[ib].k, bounce) < kFormeRoundOff);
      CHECK(relError(modes[1 - ib].k, rocking) < kFormeRoundOff);
      CHECK(modes[ib].phi == 0);
      CHECK(modes[ib].n == std::numeric_limits<double>::infinity());
      CHECK(modes[1 - ib].z == 0);
      CHECK(modes[1 - ib].n == 0);
      // Bounce loads both springs in phase; rocking loads them against each other with
      // equal forces (C1 l1 = C2 l2), so the net force is zero.
      CHECK(modes[ib].FA * modes[ib].FB > 0);
      CHECK(std::abs(modes[1 - ib].FA + modes[1 - ib].FB) <=
            kFormeRoundOff * std::abs(modes[1 - ib].FA));

      // Continuity: a tiny b gives a coupled mode with a huge but finite n, the same
      // frequencies to second order in b, and nearly the same shapes.
      FormeShaftRigid t = s;
      t.l2 *= 1 + 1e-9;
      const auto near = formeShaftModes(t);
      CHECK(near[ib].kind == FormeModeKind::coupled);
      CHECK(std::isfinite(near[ib].n));
      CHECK(std::abs(near[ib].n) > 1e6);
      CHECK(std::abs(near[1 - ib].n) < 1e-6);
      CHECK(relError(near[ib].k, bounce) < 1e-9);
      CHECK(std::abs(near[ib].z - 1) < 1e-12);
    }
  }

  TEST_CASE("FE rigid-body properties equal the section integrals") {
    const FormeShaftDesign design;
    const RigidBodyProperties ref = sectionIntegrals(design);
    for (DofSet dofs : {DofSet::planar(), DofSet::lateral()}) {
      const FormeShaftModel fe = buildFormeShaft(design, dofs);
      const RigidBodyProperties p = rigidBodyProperties(fe.model);
      // The consistent mass reproduces rigid motion exactly: round-off only.
      CHECK(relError(p.m, ref.m) < kFormeRoundOff);
      CHECK(relError(p.xG, ref.xG) < kFormeRoundOff);
      CHECK(relError(p.J, ref.J) < kFormeRoundOff);
      if (dofs == DofSet::lateral()) CHECK(relError(p.Jp, ref.Jp) < kFormeRoundOff);
      CHECK(relError(fe.xA, 0.08) < kFormeRoundOff);
      CHECK(relError(fe.xB, 1.29) < kFormeRoundOff);
    }
    MESSAGE("forme shaft: m = " << ref.m << " kg, centre of mass at x = " << ref.xG
                                << " m (bearings at 0.08 and 1.29 m), J = " << ref.J
                                << " kg m^2, Jp = " << ref.Jp << " kg m^2");
  }

  TEST_CASE("rigid limit: as E grows the two lowest FE frequencies reach k1, k2") {
    FormeShaftDesign design = stiff(FormeShaftDesign{});
    double previous = 0;
    for (double E : {2e13, 2e15, 2e17}) {
      design.E = E;
      const FormeShaftModel fe = buildFormeShaft(design, DofSet::planar());
      const FormeShaftRigid s =
          rigidModel(rigidBodyProperties(fe.model), fe.xA, fe.xB, design.C1, design.C2);
      const auto modes = formeShaftModes(s);
      const auto w = lowestTwo(fe.model);
      const double err = std::max(relError(w[0], modes[0].k), relError(w[1], modes[1].k));
      MESSAGE("E = " << E << ": largest relative gap to k1, k2 = " << err);
      // The gap is the shaft's flexibility, ~ C / k_shaft, so it falls as 1/E (measured
      // 6.0e-4, 6.0e-6) until round-off, ~ eps k_element / C, joins in at E = 2e17 (measured
      // 6.6e-8 where flexibility alone would give 6.0e-8).
      if (E == 2e15) CHECK(previous / err == doctest::Approx(100).epsilon(0.01));
      previous = err;
      if (E == 2e17) CHECK(err < 1e-6);
    }
  }

  TEST_CASE("real steel: flexibility lowers k1, k2 by a measured amount within Weyl's bound") {
    // With the spring flexibility F_b (rigid body on springs) and the shaft's own F_s (shaft
    // pinned at A and B), the statically determinate support gives F = F_b + F_s, and Weyl's
    // inequality for 1/omega^2 = eig(M^1/2 F M^1/2) bounds each frequency from below:
    //   1/omega_i^2 <= 1/k_i^2 + 1/omega_s^2,   omega_s the pinned shaft's first bending
    // frequency. Adding flexibility also only lowers frequencies: omega_i < k_i.
    const FormeShaftDesign design;
    const FormeShaftModel fe = buildFormeShaft(design, DofSet::planar());
    const FormeShaftRigid s =
        rigidModel(rigidBodyProperties(fe.model), fe.xA, fe.xB, design.C1, design.C2);
    const auto modes = formeShaftModes(s);
    const auto w = lowestTwo(fe.model);

    FormeShaftDesign pinnedDesign = design;
    pinnedDesign.C1 = pinnedDesign.C2 = 0;
    FormeShaftModel pinned = buildFormeShaft(pinnedDesign, DofSet::planar());
    pinned.model.addSupport({"A", pinned.nodeA, {{Dof::uy, 0}}});
    pinned.model.addSupport({"B", pinned.nodeB, {{Dof::uy, 0}}});
    const ModalResult pr = solveModes(pinned.model, {4, 0});
    double ws = 0;
    for (const Mode& m : pr.modes)
      if (m.description.starts_with("bending")) {
        ws = std::sqrt(m.eigenvalue);
        break;
      }
    REQUIRE(ws > 0);

    // Mesh convergence: Timoshenko elements shorter than the section depth (0.05 m in a
    // 0.3 m barrel) converge at rate 2 (see test_frequencies.cpp), so the change from halving
    // the element size (measured 1.0e-5 and 1.7e-5) is 3/4 of the error left: the drop
    // below is the model's, not the mesh's, to ~2e-5 of a ~6 % effect.
    FormeShaftDesign fine = design, finer = design;
    fine.elementSize /= 2;
    finer.elementSize /= 4;
    const auto wf = lowestTwo(buildFormeShaft(fine, DofSet::planar()).model);
    const auto wff = lowestTwo(buildFormeShaft(finer, DofSet::planar()).model);

    for (int i = 0; i < 2; ++i) {
      CAPTURE(i);
      const double drop = 1 - w[i] / modes[i].k;
      const double bound = 1 - 1 / std::sqrt(1 + std::pow(modes[i].k / ws, 2));
      MESSAGE("mode " << i + 1 << ": rigid k = " << modes[i].k << " rad/s, FE " << w[i]
                      << " rad/s: " << 100 * drop << " % lower (Weyl bound " << 100 * bound
                      << " %, pinned shaft " << ws << " rad/s)");
      CHECK(drop > 0);
      CHECK(drop <= bound);
      CHECK(relError(wf[i], w[i]) < 3e-5);
      // (measured 4.01, 4.05: the 0.14 m piece between B and the gear is cut 3, 6, 12 times
      // but the 0.08 m pieces 2, 4, 7 times).
      CHECK((w[i] - wf[i]) / (wf[i] - wff[i]) == doctest::Approx(4).epsilon(0.05));
    }
  }

  TEST_CASE("decoupled FE shaft (C1 l1 = C2 l2): pure bounce and pure rocking") {
    FormeShaftDesign design = stiff(FormeShaftDesign{});
    const RigidBodyProperties body =
        rigidBodyProperties(buildFormeShaft(design, DofSet::planar()).model);
    design.C2 = design.C1 * (body.xG - 0.08) / (1.29 - body.xG);
    const FormeShaftModel fe = buildFormeShaft(design, DofSet::planar());
    const FormeShaftRigid s = rigidModel(body, fe.xA, fe.xB, design.C1, design.C2);
    const auto modes = formeShaftModes(s);
    const int ib = modes[0].kind == FormeModeKind::bounce ? 0 : 1;
    REQUIRE(modes[ib].kind == FormeModeKind::bounce);
    REQUIRE(modes[1 - ib].kind == FormeModeKind::rocking);
    const ModalResult r = solveModes(fe.model, {2, 0});
    for (int i = 0; i < 2; ++i) {
      CAPTURE(i);
      CHECK(relError(std::sqrt(r.modes[i].eigenvalue), modes[i].k) < 1e-6);
    }
    // FE shapes: the bounce mode barely rotates, the rocking mode turns about the centre of
    // mass (its translation there vanishes). Measured ratios ~1e-8: the residual flexibility.
    const NodalField& bounce = r.modes[ib].shape;
    const NodalField& rocking = r.modes[1 - ib].shape;
    const double rho = std::sqrt(s.rho2());
    const int a = fe.nodeA;
    CHECK(rho * std::abs(bounce(a, 5)) < 1e-6 * std::abs(bounce(a, 1)));
    // Translation of the rocking mode at the centre of mass, from A's: uy(G) = uy(A) +
    // rz (xG - xA).
    const double uyG = rocking(a, 1) + rocking(a, 5) * (body.xG - fe.xA);
    CHECK(std::abs(uyG) < 1e-6 * rho * std::abs(rocking(a, 5)));
  }

  TEST_CASE("rotor extension: the spinning rigid shaft whirls as the closed form says") {
    // b = 0, isotropic bearings: bounce sqrt(a) twice, conical whirl forward and backward.
    FormeShaftDesign design = stiff(FormeShaftDesign{});
    const RigidBodyProperties body =
        rigidBodyProperties(buildFormeShaft(design, DofSet::lateral()).model);
    design.C2 = design.C1 * (body.xG - 0.08) / (1.29 - body.xG);
    const FormeShaftModel fe = buildFormeShaft(design, DofSet::lateral());
    const FormeShaftRigid s = rigidModel(body, fe.xA, fe.xB, design.C1, design.C2);
    // A B1 press runs up to ~18000 sheets/h, one cylinder turn per sheet: 300 rpm = 31 rad/s,
    // where the gyroscopic split is tiny; the sweep goes far beyond to test the closed form.
    double worst = 0;
    for (double W : {0.0, 31.4, 1000.0, 3000.0, 10000.0}) {
      CAPTURE(W);
      RotorOptions opts;
      opts.modes = 4;
      const RotorModesResult r = solveRotorModes(fe.model, W, opts);
      REQUIRE(r.modes.size() == 4);
      std::vector<double> got,
          ref{std::sqrt(s.a()), std::sqrt(s.a()), formeShaftWhirl(s, body.Jp, W, +1),
              formeShaftWhirl(s, body.Jp, W, -1)};
      for (const RotorMode& m : r.modes) got.push_back(m.dampedFrequency);
      std::sort(got.begin(), got.end());
      std::sort(ref.begin(), ref.end());
      for (int k = 0; k < 4; ++k) {
        worst = std::max(worst, relError(got[k], ref[k]));
        CHECK(relError(got[k], ref[k]) < 1e-6);
      }
      if (W >= 1000)
        for (const RotorMode& m : r.modes)
          if (relError(m.dampedFrequency, formeShaftWhirl(s, body.Jp, W, +1)) < 1e-6)
            CHECK(m.whirl == Whirl::forward);
    }
    MESSAGE("spinning forme shaft: largest relative error against the closed form " << worst);
  }
}

// Damped rotor modes against closed forms: the rigid rotor's conical whirl
// (problems/scenes/README.md section 2, rotor extension), proportional damping, a cross-coupled
// bearing, and the non-rotating shaft against the symmetric modal solver.
#include <doctest/doctest.h>

#include <algorithm>
#include <cmath>
#include <complex>
#include <tuple>

#include "elements/Bearing.hpp"
#include "elements/PointInertia.hpp"
#include "elements/Spring.hpp"
#include "fem/modal/Modal.hpp"
#include "fem/rotor/RotorModes.hpp"
#include "fem/solvers/Errors.hpp"
#include "tests/Helpers.hpp"
#include "tests/fem/rotor/RotorTestSupport.hpp"

using namespace beamrotor;
using namespace beamrotor::test;

namespace {

/// Shaft along x from 0 to L (solid circle D, density rho, modulus E) with a disk at xd,
/// bearings at xa and xb; b = 0 (C1 l1 = C2 l2) so bounce and tilt decouple. Coarse mesh: the
/// rigid limit needs no refinement, and a coarse mesh keeps the very stiff shaft's element
/// stiffness (and the round-off it brings to the soft rigid-body modes) small.
struct ModesRigidRotor {
  double L = 1.0, D = 0.1, E = 2e17, rho = 7850;
  double xd = 0.7, md = 30, Jpd = 0.6, Jdd = 0.35;
  double xa = 0.1, xb = 0.9, C1 = 1e7;

  // Rigid-body properties from section integrals (independent of the FE matrices).
  double A() const { return std::numbers::pi * D * D / 4; }
  double I() const { return std::numbers::pi * std::pow(D, 4) / 64; }
  double ms() const { return rho * A() * L; }
  double m() const { return ms() + md; }
  double xG() const { return (ms() * L / 2 + md * xd) / m(); }
  double Jp() const { return rho * 2 * I() * L + Jpd; }
  double Jd() const {  // about the centre of mass: shaft (with its rotary inertia rho I L) + disk
    return ms() * L * L / 12 + rho * I() * L + ms() * std::pow(L / 2 - xG(), 2) + Jdd +
           md * std::pow(xd - xG(), 2);
  }
  double l1() const { return xG() - xa; }
  double l2() const { return xb - xG(); }
  double C2() const { return C1 * l1() / l2(); }
  double kPhi() const { return C1 * l1() * l1() + C2() * l2() * l2(); }

  double bounce() const { return std::sqrt((C1 + C2()) / m()); }
  double forward(double W) const {
    return (Jp() * W + std::sqrt(std::pow(Jp() * W, 2) + 4 * Jd() * kPhi())) / (2 * Jd());
  }
  double backward(double W) const {
    return (-Jp() * W + std::sqrt(std::pow(Jp() * W, 2) + 4 * Jd() * kPhi())) / (2 * Jd());
  }

  void build(Model& model, int perPiece = 1) const {
    auto sec = std::make_shared<Section>(
        Section::circle("shaft", Material::fromEnu("stiff", E, 0.3, rho), D));
    LineSpec spec;
    spec.dofs = DofSet::lateral();
    spec.segments.push_back(
        {L, sec, 4 * perPiece, 0, {BeamTheory::timoshenko, MassModel::consistent, true}});
    spec.points = {{"A", xa}, {"B", xb}, {"disk", xd}};
    buildLine(model, spec);
    model.add<PointInertia>(model.node("disk"), DofSet::lateral(), md, Jpd, Jdd);
    model.add<Bearing>(model.node("A"), BearingCoefficients::isotropic(C1));
    model.add<Bearing>(model.node("B"), BearingCoefficients::isotropic(C2()));
  }
};

/// || (lambda^2 M + lambda D + K) q || / (||K|| ||q||) for a computed mode.
double residual(const RotorSystem& sys, double speed, Complex lambda, const Eigen::VectorXcd& q) {
  const Eigen::MatrixXcd K = Eigen::MatrixXd(sys.stiffness(speed)).cast<Complex>();
  const Eigen::MatrixXcd D =
      Eigen::MatrixXd(sys.damping(speed) + speed * sys.gyroscopic()).cast<Complex>();
  const Eigen::MatrixXcd M = Eigen::MatrixXd(sys.mass()).cast<Complex>();
  return ((lambda * lambda * M + lambda * D + K) * q).norm() / (K.norm() * q.norm());
}

}  // namespace

TEST_SUITE("rotor modes") {
  TEST_CASE("rigid rotor, b = 0: bounce sqrt((C1+C2)/m), conical whirl closed form") {
    const ModesRigidRotor r;
    Model model;
    r.build(model);
    const RotorSystem sys(model);
    // Measured: largest error 1.1e-7 over the speeds, from the stiff shaft's flexibility
    // (C / k_shaft ~ 2e-7 in omega^2) and round-off (eps k_element / C ~ 1e-8).
    const double tolerance = 1e-6;
    double worst = 0;
    for (double W : {0.0, 200.0, 500.0, 1000.0, 2000.0, 5000.0}) {
      CAPTURE(W);
      for (EigenMethod method : {EigenMethod::dense, EigenMethod::arnoldi}) {
        QuadraticEigenSolver solver;
        const RotorModesResult res =
            solveRotorModes(sys, W, rotorOptions(4, 0, {}, method), solver);
        REQUIRE(res.modes.size() == 4);
        // Two bounce modes (y and z), then the backward and forward conical modes.
        std::vector<double> fe, ref{r.bounce(), r.bounce(), r.backward(W), r.forward(W)};
        for (const RotorMode& mode : res.modes) {
          fe.push_back(mode.dampedFrequency);
          // Undamped: lambda on the imaginary axis up to round-off (measured 2.3e-12).
          CHECK(std::abs(mode.dampingRatio) < 1e-10);
        }
        std::sort(fe.begin(), fe.end());
        std::sort(ref.begin(), ref.end());
        for (int k = 0; k < 4; ++k) {
          worst = std::max(worst, relError(fe[k], ref[k]));
          CHECK(relError(fe[k], ref[k]) < tolerance);
        }
        // Whirl sense of the conical modes once they are apart from the bounce pair.
        if (W >= 500)
          for (const RotorMode& mode : res.modes) {
            if (relError(mode.dampedFrequency, r.forward(W)) < tolerance)
              CHECK(mode.whirl == Whirl::forward);
            if (relError(mode.dampedFrequency, r.backward(W)) < tolerance)
              CHECK(mode.whirl == Whirl::backward);
          }
        // Backward error of each eigenpair: round-off (measured up to 1.9e-12).
        for (int k = 0; k < 4; ++k)
          CHECK(residual(sys, W, res.modes[k].eigenvalue, res.vectors.col(k)) < 1e-10);
      }
    }
    MESSAGE("rigid rotor: largest relative error against the closed form " << worst);
  }

  TEST_CASE("proportional damping: zeta = alpha / (2 omega) + beta omega / 2 on every mode") {
    // Non-rotating, so the undamped modes are real and alpha M + beta K keeps them:
    // lambda = -zeta omega +- i omega sqrt(1 - zeta^2) with omega the undamped frequency.
    Model model;
    const Line line = uniformBeam(model, 1.0, steelCircle(0.05), 10, DofSet::lateral(),
                                  {BeamTheory::timoshenko, MassModel::consistent, true});
    model.add<Bearing>(line.nodes.front(), BearingCoefficients::isotropic(5e7));
    model.add<Bearing>(line.nodes.back(), BearingCoefficients::isotropic(5e7));
    const RotorModesResult undamped = solveRotorModes(model, 0, rotorOptions(6));
    const double alpha = 3.0, beta = 2e-5;
    const RotorModesResult damped = solveRotorModes(model, 0, rotorOptions(6, 0, {alpha, beta}));
    REQUIRE(damped.modes.size() == 6);
    for (int k = 0; k < 6; ++k) {
      const double w = undamped.modes[k].dampedFrequency;
      const double zeta = alpha / (2 * w) + beta * w / 2;
      CAPTURE(k);
      CHECK(relError(damped.modes[k].naturalFrequency, w) < 1e-10);
      CHECK(relError(damped.modes[k].dampingRatio, zeta) < 1e-9);
      CHECK(relError(damped.modes[k].dampedFrequency, w * std::sqrt(1 - zeta * zeta)) < 1e-10);
      CHECK(relError(damped.modes[k].logDecrement,
                     2 * std::numbers::pi * zeta / std::sqrt(1 - zeta * zeta)) < 1e-9);
    }
  }

  TEST_CASE("cross-coupled bearing: lambda^2 m + k +- i q = 0, the forward mode unstable") {
    // A point mass on a bearing with K = [k q; -q k]: in u = uy + i uz (forward whirl
    // rotates u like e^{i w t}) the equations become m u'' + (k - i q) u = 0 and its
    // conjugate, so lambda^2 = -(k -+ i q) / m exactly.
    const double m = 12, k = 3e6, q = 4e5;
    Model model;
    const int node = model.addNode({0, 0, 0});
    model.add<PointInertia>(node, DofSet{Dof::uy, Dof::uz}, m);
    model.add<Bearing>(node, BearingCoefficients{k, q, -q, k});
    const RotorModesResult res = solveRotorModes(model, 0, rotorOptions(2));
    REQUIRE(res.modes.size() == 2);
    int unstable = 0;
    for (const RotorMode& mode : res.modes) {
      const Complex l2 = mode.eigenvalue * mode.eigenvalue;
      const bool fwd = mode.whirl == Whirl::forward;
      const Complex expected = -Complex(k, fwd ? -q : q) / m;
      CHECK(std::abs(l2 - expected) < 1e-12 * std::abs(expected));
      if (mode.dampingRatio < 0) {
        ++unstable;
        CHECK(fwd);
        CHECK(mode.logDecrement < 0);
      }
      CHECK(std::abs(std::abs(mode.whirlRatio) - 1) < 1e-12);  // circular orbits
    }
    CHECK(unstable == 1);
  }

  TEST_CASE("tabulated cross-coupled bearing: the coefficients interpolated at the speed") {
    // The closed form of the case above with k and q read off a two-row table at the spin
    // speed: (3e6, 0) N/m at rest and (5e6, 8e5) at 1000 rad/s give k = 3.5e6 and q = 2e5 at
    // 250 rad/s, held at the last row beyond it. The table's speed dependence reaches the
    // matrices through the rotor system's per-speed update, not through the rest state.
    const double m = 12;
    Model model;
    const int node = model.addNode({0, 0, 0});
    model.add<PointInertia>(node, DofSet{Dof::uy, Dof::uz}, m);
    model.add<Bearing>(node, std::vector<double>{0, 1000},
                       std::vector<BearingCoefficients>{{3e6, 0, 0, 3e6}, {5e6, 8e5, -8e5, 5e6}});
    for (auto [speed, k, q] : {std::tuple{250.0, 3.5e6, 2e5}, std::tuple{1500.0, 5e6, 8e5}}) {
      CAPTURE(speed);
      const RotorModesResult res = solveRotorModes(model, speed, rotorOptions(2));
      REQUIRE(res.modes.size() == 2);
      for (const RotorMode& mode : res.modes) {
        const Complex expected = -Complex(k, mode.whirl == Whirl::forward ? -q : q) / m;
        CHECK(std::abs(mode.eigenvalue * mode.eigenvalue - expected) < 1e-12 * std::abs(expected));
      }
    }
  }

  TEST_CASE("non-rotating uniform shaft: each planar frequency twice (eigenspaces)") {
    // Simply supported Timoshenko shaft with rotary inertia, 40 elements: 160 free lateral
    // dofs, 320 state variables, so the Arnoldi path runs. The planar model (ux held along
    // the line, uy at the ends) has the same bending frequencies once; the lateral one twice.
    const auto sec = steelCircle(0.05);
    const BeamOptions opts{BeamTheory::timoshenko, MassModel::consistent, true};
    Model planar, lateral;
    const Line lp = uniformBeam(planar, 1.0, sec, 40, DofSet::planar(), opts);
    const Line ll = uniformBeam(lateral, 1.0, sec, 40, DofSet::lateral(), opts);
    for (int node : lp.nodes)
      planar.addSupport({"axial" + std::to_string(node), node, {{Dof::ux, 0}}});
    for (int end : {0, 1}) {
      const int np = end ? lp.nodes.back() : lp.nodes.front();
      const int nl = end ? ll.nodes.back() : ll.nodes.front();
      const std::string index = std::to_string(end);
      planar.addSupport({"p" + index, np, {{Dof::uy, 0}}});
      lateral.addSupport({"l" + index, nl, {{Dof::uy, 0}, {Dof::uz, 0}}});
    }
    const ModalResult ref = solveModes(planar, {4, 0});
    const RotorModesResult rot = solveRotorModes(lateral, 0, rotorOptions(8));
    REQUIRE(rot.modes.size() == 8);
    REQUIRE(ref.modes.size() == 4);
    std::vector<double> hz;
    for (const RotorMode& mode : rot.modes) hz.push_back(mode.dampedFrequencyHz);
    std::sort(hz.begin(), hz.end());
    double worst = 0;
    for (int k = 0; k < 4; ++k)
      for (int j : {2 * k, 2 * k + 1})
        worst = std::max(worst, relError(hz[j], ref.modes[k].frequencyHz));
    MESSAGE("non-rotating shaft: largest relative gap to the planar frequencies " << worst);
    for (int k = 0; k < 4; ++k) {
      CAPTURE(k);
      // Both solvers converge to round-off (measured 1.0e-12); 1e-9 leaves room for the
      // conditioning of the non-symmetric Arnoldi iteration on a double eigenvalue.
      CHECK(relError(hz[2 * k], ref.modes[k].frequencyHz) < 1e-9);
      CHECK(relError(hz[2 * k + 1], ref.modes[k].frequencyHz) < 1e-9);
    }
  }

  TEST_CASE("complex shift finds the modes around a frequency; same eigenvalues as shift 0") {
    ModesRigidRotor r;
    r.E = 2.1e11;  // a real shaft, so that elastic modes follow the rigid ones
    Model model;
    r.build(model, 4);
    const double W = 800;
    const RotorModesResult low = solveRotorModes(model, W, rotorOptions(6));
    // Shift near the fourth mode's frequency (not on it: P(shift) would be singular): the
    // mode nearest it, found by znaupd, is that mode.
    const double w4 = low.modes[3].dampedFrequency;
    const RotorModesResult around = solveRotorModes(
        model, W, rotorOptions(2, Complex(0, 1.001 * w4), {}, EigenMethod::arnoldi));
    REQUIRE(!around.modes.empty());
    CHECK(relError(around.modes[0].dampedFrequency, w4) < 1e-10);
  }

  TEST_CASE("shift 0 on a free-free rotor names the problem; a negative shift works") {
    Model model;
    const auto sec = steelCircle(0.05);
    uniformBeam(model, 1.0, sec, 10, DofSet::lateral());
    CHECK_THROWS_AS(solveRotorModes(model, 0, rotorOptions(4)), SolveError);
    const RotorModesResult res = solveRotorModes(model, 0, rotorOptions(6, -1.0));
    REQUIRE(res.modes.size() == 6);
    // Four rigid-body modes (two translations, two tilts): lambda = 0 with a Jordan block
    // (q = a + b t), which any eigensolver resolves only to ~sqrt(eps) of the problem's scale
    // (measured 1.3e-4 rad/s, 9e-8 of the first elastic frequency). Then the first free-free
    // bending pair, beta L = 4.730041 (10 elements: 1e-5 discretisation error).
    const double elastic = std::pow(4.730041, 2) * std::sqrt(sec->EIz() / sec->rhoA());
    for (int k = 0; k < 4; ++k) CHECK(res.modes[k].naturalFrequency < 1e-6 * elastic);
    for (int k = 4; k < 6; ++k) CHECK(relError(res.modes[k].naturalFrequency, elastic) < 1e-4);
  }

  TEST_CASE("a free-free rotor's rigid-body zero split into real +-delta is one mode") {
    // Shift -100: ARPACK resolves each rigid-body Jordan block as a real pair +-delta (measured
    // |delta| = 3.4e-4 to 4.1e-4 rad/s at 10 elements, 3.5e-2 at 100), not as +-i delta. Before,
    // both members counted as modes: the six modes asked for were six rigid-body ones and the
    // first bending pair was left out. Reference: free-free beta L = 4.730041 (Blevins, table
    // 8-1; 7 digits cost 2e-7 on (beta L)^2), one pair for the two bending planes.
    const auto sec = steelCircle(0.05);
    const double elastic = std::pow(4.730041, 2) * std::sqrt(sec->EIz() / sec->rhoA());
    for (int elements : {10, 100}) {
      CAPTURE(elements);
      Model model;
      uniformBeam(model, 1.0, sec, elements, DofSet::lateral());
      const RotorModesResult res = solveRotorModes(model, 0, rotorOptions(6, -100.0));
      REQUIRE(res.modes.size() == 6);
      // Four rigid-body modes (two translations, two tilts), each once: zero to the Jordan
      // split's sqrt(eps)-sized round-off (measured 2.9e-7 and 2.5e-5 of the bending frequency).
      for (int k = 0; k < 4; ++k) CHECK(res.modes[k].naturalFrequency < 1e-4 * elastic);
      // Then the bending pair: 10 elements carry 1e-5 discretisation error (h^4), 100 elements
      // 1e-9, below the reference's own 2e-7.
      for (int k = 4; k < 6; ++k)
        CHECK(relError(res.modes[k].naturalFrequency, elastic) < (elements == 10 ? 1e-4 : 1e-6));
    }
  }
}

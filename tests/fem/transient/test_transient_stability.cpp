// Stability of the time-stepping schemes on a small cantilever with lumped mass
// (problems/scenes/README.md, "where methods fail": explicit stepping beyond dt = 2 / omega_max
// diverges, implicit average acceleration does not), and the high-frequency damping of HHT.
#include <doctest/doctest.h>

#include <Eigen/Eigenvalues>
#include <cmath>

#include "fem/assembly/ReducedSystem.hpp"
#include "fem/solvers/Errors.hpp"
#include "fem/transient/Transient.hpp"
#include "fem/transient/TransientCentral.hpp"
#include "tests/Helpers.hpp"

using namespace beamrotor;
using namespace beamrotor::test;

namespace {

/// Steel cantilever, 1.5 m, 40 mm, bending in x-y, lumped mass with rotary inertia (so every
/// dof has mass and central difference applies). Tip point "end".
Line lumpedCantilever(Model& m, int elements) {
  const Line line = uniformBeam(m, 1.5, steelCircle(0.04), elements, DofSet{Dof::uy, Dof::rz},
                                {BeamTheory::eulerBernoulli, MassModel::lumped, true});
  clamp(m, "root", line.nodes.front(), DofSet{Dof::uy, Dof::rz});
  return line;
}

/// All generalised eigenpairs of the free-free blocks, dense: the independent reference.
Eigen::GeneralizedSelfAdjointEigenSolver<Eigen::MatrixXd> denseModes(const Model& m,
                                                                     const DofMap& dofs) {
  const SparseAssembler a(m, dofs);
  const Eigen::MatrixXd K(a.assemble(MatrixKind::stiffness)), M(a.assemble(MatrixKind::mass));
  return Eigen::GeneralizedSelfAdjointEigenSolver<Eigen::MatrixXd>(K, M);
}

/// A smooth initial bend u = (x / L)^2 * 1 mm with its slope on rz: it holds every mode.
NodalField parabola(const Model& m, const Line& line) {
  NodalField u = NodalField::Zero(m.nodeCount(), kDofKinds);
  const double L = line.stations.back();
  for (std::size_t i = 0; i < line.nodes.size(); ++i) {
    const double s = line.stations[i] / L;
    u(line.nodes[i], dofIndex(Dof::uy)) = 1e-3 * s * s;
    u(line.nodes[i], dofIndex(Dof::rz)) = 1e-3 * 2 * s / L;
  }
  return u;
}

double maxAbs(const std::vector<double>& v, std::size_t from = 0) {
  double m = 0;
  for (std::size_t i = from; i < v.size(); ++i) m = std::max(m, std::abs(v[i]));
  return m;
}

}  // namespace

TEST_SUITE("transient stability") {
  TEST_CASE("critical step 2/omega_max against the dense eigenvalues") {
    for (int elements : {8, 40}) {  // 16 dofs: dense path; 80 dofs: ARPACK Lanczos
      CAPTURE(elements);
      Model m;
      lumpedCantilever(m, elements);
      const StabilityLimit limit = centralDifferenceLimit(m);
      const double omegaMax = std::sqrt(denseModes(m, DofMap(m)).eigenvalues().maxCoeff());
      MESSAGE(elements << " elements (" << limit.method << "): omega_max " << limit.omegaMax
                       << " rad/s, dt_crit " << limit.dtCritical << " s; Gershgorin bound "
                       << limit.omegaMaxBound << " rad/s");
      // Both eigensolvers are converged to near machine precision (Lanczos tolerance 1e-12).
      CHECK(relError(limit.omegaMax, omegaMax) < 1e-9);
      CHECK(relError(limit.dtCritical, 2 / omegaMax) < 1e-9);
      CHECK(limit.omegaMaxBound >= omegaMax * (1 - 1e-12));
      CHECK(limit.dtCriticalSafe <= limit.dtCritical);
      CHECK(limit.method == (elements == 8 ? "dense" : "arpack-lanczos"));
    }
  }

  TEST_CASE("central difference diverges at 1.01 dt_crit and stays bounded at 0.99 dt_crit") {
    Model m;
    const Line line = lumpedCantilever(m, 8);
    const double dtCrit = centralDifferenceLimit(m).dtCritical;
    const int tip = line.nodes.back();
    auto run = [&](double factor) {
      TransientOptions opt;
      opt.scheme = TimeScheme::centralDifference;
      opt.timeStep = factor * dtCrit;
      opt.endTime = 400 * opt.timeStep;
      opt.initialDisplacement = parabola(m, line);
      opt.histories = {{tip, Dof::uy}};
      return solveTransient(m, opt);
    };
    const TransientResult below = run(0.99), above = run(1.01);
    const double u0 = 1e-3;
    const double growthBelow = maxAbs(below.histories[0].displacement) / u0;
    const double growthAbove = maxAbs(above.histories[0].displacement, 350) / u0;
    MESSAGE("tip amplitude / initial over 400 steps: " << growthBelow << " at 0.99 dt_crit, "
                                                       << growthAbove << " at 1.01 dt_crit");
    // Above the limit the top mode is amplified by |lambda| = 1.33 a step (Omega = 2.02): even
    // from round-off it passes 1e6 within 400 steps. Below, the discrete energy is conserved
    // and the tip stays within a few times its initial deflection.
    CHECK(growthAbove > 1e6);
    CHECK(growthBelow < 3);
    CHECK(below.warnings.empty());
    REQUIRE(above.warnings.size() >= 1);
    CHECK(above.warnings[0].find("critical step") != std::string::npos);
    CHECK(above.stability.dtCritical == dtCrit);
  }

  TEST_CASE("newmark average acceleration conserves energy at 10 dt_crit") {
    Model m;
    const Line line = lumpedCantilever(m, 8);
    TransientOptions opt;
    opt.timeStep = 10 * centralDifferenceLimit(m).dtCritical;
    opt.endTime = 2000 * opt.timeStep;
    opt.initialDisplacement = parabola(m, line);
    const TransientResult r = solveTransient(m, opt);
    const double E0 = r.energy.kinetic[0] + r.energy.strain[0];
    double drift = 0;
    for (std::size_t n = 0; n < r.times.size(); ++n)
      drift = std::max(drift, std::abs(r.energy.kinetic[n] + r.energy.strain[n] - E0) / E0);
    MESSAGE("newmark at 10 dt_crit, 2000 steps: relative energy drift " << drift);
    // Undamped, unloaded: the rule conserves kinetic + strain energy exactly, so the drift is
    // the round-off of 2000 solves (~1e-13 measured).
    CHECK(drift < 1e-10);
    CHECK(r.factorizations == 1);
  }

  TEST_CASE("HHT damps the highest mode and barely touches the lowest") {
    Model m;
    lumpedCantilever(m, 8);
    const DofMap dofs(m);
    const auto modes = denseModes(m, dofs);
    const int top = int(modes.eigenvalues().size()) - 1;
    const double w1 = std::sqrt(modes.eigenvalues()[0]);
    // dt = T1 / 40: the first mode is well resolved (omega dt = 0.16), the top one not at all.
    const double dt = 2 * std::numbers::pi / w1 / 40;
    auto energyRatio = [&](int mode, TimeScheme scheme, double alpha) {
      TransientOptions opt;
      opt.scheme = scheme;
      opt.hhtAlpha = alpha;
      opt.timeStep = dt;
      opt.endTime = 80 * dt;  // two periods of the first mode
      opt.initialDisplacement = freeToNodalField(m, dofs, 1e-3 * modes.eigenvectors().col(mode));
      const TransientResult r = solveTransient(m, opt);
      const auto& e = r.energy;
      return (e.kinetic.back() + e.strain.back()) / (e.kinetic[0] + e.strain[0]);
    };
    MESSAGE("omega_top dt = " << std::sqrt(modes.eigenvalues()[top]) * dt);
    for (double alpha : {-0.1, -0.3}) {
      CAPTURE(alpha);
      const double high = energyRatio(top, TimeScheme::hht, alpha);
      const double low = energyRatio(0, TimeScheme::hht, alpha);
      MESSAGE("alpha " << alpha << ": energy left after 80 steps, top mode " << high
                       << ", first mode " << low);
      // Spectral radius (1 + alpha) / (1 - alpha) per step as omega dt -> infinity: 0.82 and
      // 0.54. The unresolved mode's velocity first overshoots omega u by up to ~Omega = 187
      // (the start-up acceleration -omega^2 u enters v through gamma dt a), so its energy
      // falls as Omega^2 0.82^(2n): ~4e-10 after 80 steps for alpha = -0.1.
      CHECK(high < 1e-6);
      // At Omega = 0.16 the spectral radius is 1 - 6e-6 (alpha = -0.1) or 1 - 1.1e-5 (-0.3)
      // a step, so 80 steps keep more than 99.8 % of the first mode's energy.
      CHECK(low > 0.998);
    }
    // The average acceleration rule keeps both.
    CHECK(std::abs(energyRatio(top, TimeScheme::newmark, 0) - 1) < 1e-10);
  }

  TEST_CASE("central difference refuses consistent mass and massless dofs, naming them") {
    TransientOptions opt;
    opt.scheme = TimeScheme::centralDifference;
    opt.timeStep = 1e-6;
    opt.endTime = 1e-5;
    SUBCASE("consistent mass") {
      Model m;
      uniformBeam(m, 1, steelCircle(0.04), 4, DofSet{Dof::uy, Dof::rz});
      clamp(m, "root", 0, DofSet{Dof::uy, Dof::rz});
      CHECK_THROWS_WITH_AS(solveTransient(m, opt), doctest::Contains("MassModel::lumped"),
                           SolveError);
    }
    SUBCASE("lumped mass without rotary inertia leaves the rotations massless") {
      Model m;
      uniformBeam(m, 1, steelCircle(0.04), 4, DofSet{Dof::uy, Dof::rz},
                  {BeamTheory::eulerBernoulli, MassModel::lumped, false});
      clamp(m, "root", 0, DofSet{Dof::uy, Dof::rz});
      CHECK_THROWS_WITH_AS(solveTransient(m, opt), doctest::Contains("rz"), SolveError);
      // The implicit scheme copes: massless rotations follow from equilibrium.
      opt.scheme = TimeScheme::newmark;
      opt.initialVelocity = NodalField::Zero(m.nodeCount(), kDofKinds);
      opt.initialVelocity(m.node("end"), dofIndex(Dof::uy)) = 1;
      const TransientResult r = solveTransient(m, opt);
      CHECK(r.steps == 10);
    }
  }
}

// Timoshenko against Euler-Bernoulli on the variant A pump rod (problems/scenes/README.md section
// 1), chosen from the command line (`--formulation timoshenko`) for a deck written for
// Euler-Bernoulli. The reference is the initial-parameter closed form of pump_rod.yaml with the
// shear flexibility added, written here; the interdependent-interpolation Timoshenko element is
// exact for the static beam without span loads, so the two agree to round-off.
#include <doctest/doctest.h>

#include <Eigen/Dense>
#include <cmath>
#include <numbers>

#include "tests/Helpers.hpp"
#include "tests/problems/DeckTestSupport.hpp"

using namespace beamrotor;
using namespace beamrotor::test;

namespace {

/// ShearReactions on the rod: left force and moment, middle force, right force and moment.
using ShearReactions = Eigen::Matrix<double, 5, 1>;

/// Timoshenko beam (e.g. Timoshenko & Gere, Mechanics of Materials; Reddy, "On locking-free
/// shear deformable beam finite elements", 1997): M = EI theta', Q = kappa G A (w' - theta),
/// M' = -Q, so w' = theta - M' / (kappa G A). With M(x) = M0 + V0 x + R <x - psi>,
/// theta(0) = 0, w(0) = -w0 (left clamp), the conditions w(psi) = 0, w(l) = 0, theta(l) = 0
/// give M0, V0, R. The shear term adds -V0 S(0, x) - R S(psi, x), S(p, x) = int_p^x ds /
/// (kappa G A), to w; `shear` = false drops it (Euler-Bernoulli).
ShearReactions closedForm(double eta, double w0, bool shear) {
  const double a = 0.575, d = 1.130, D1 = 0.120, D2 = 0.070, E = 200e9, nu = 0.3;
  const double psi = a + 0.715 - eta, l = a + d, G = E / (2 * (1 + nu));
  const double kappa = 6 * (1 + nu) / (7 + 6 * nu);  // Cowper, solid circle
  const double pi = std::numbers::pi;
  const double EI1 = E * pi * std::pow(D1, 4) / 64, EI2 = E * pi * std::pow(D2, 4) / 64;
  const double kGA1 = shear ? kappa * G * pi * D1 * D1 / 4 : INFINITY;
  const double kGA2 = shear ? kappa * G * pi * D2 * D2 / 4 : INFINITY;
  // Bending influence integrals B_k(x) = int_0^x (x - s) f_k(s) / EI ds, A_k(l) = int f_k / EI
  // for f = 1, s, <s - psi>, over the step at a < psi.
  const auto B1 = [&](double x) {
    return (x * a - a * a / 2) / EI1 + (x - a) * (x - a) / (2 * EI2);
  };
  const auto B2 = [&](double x) {
    return (x * a * a / 2 - a * a * a / 3) / EI1 +
           (x * (x * x - a * a) / 2 - (x * x * x - a * a * a) / 3) / EI2;
  };
  const double B3l = std::pow(l - psi, 3) / (6 * EI2);
  const double A1l = a / EI1 + (l - a) / EI2, A2l = a * a / (2 * EI1) + (l * l - a * a) / (2 * EI2);
  const double A3l = (l - psi) * (l - psi) / (2 * EI2);
  const auto S0 = [&](double x) { return a / kGA1 + (x - a) / kGA2; };
  Eigen::Matrix3d K;
  K << B1(psi), B2(psi) - S0(psi), 0,                //
      B1(l), B2(l) - S0(l), B3l - (l - psi) / kGA2,  //
      A1l, A2l, A3l;
  const Eigen::Vector3d x = K.lu().solve(Eigen::Vector3d(w0, w0, 0));
  const double M0 = x[0], V0 = x[1], R = x[2];
  ShearReactions r;
  r << V0, -M0, R, -(V0 + R), M0 + V0 * l + R * (l - psi);
  return r;
}

ShearReactions deckReactions(const RunResult& run) {
  ShearReactions r;
  r << staticReaction(run, "left", Dof::uy), staticReaction(run, "left", Dof::rz),
      staticReaction(run, "middle", Dof::uy), staticReaction(run, "right", Dof::uy),
      staticReaction(run, "right", Dof::rz);
  return r;
}

// Exact elements on both sides: round-off only (condition of K ~1e7), as for the EB decks.
constexpr double kTimoshenkoExact = 1e-9;

}  // namespace

TEST_SUITE("pump rod timoshenko") {
  TEST_CASE("--formulation timoshenko: reactions equal the closed form with shear flexibility") {
    // A sweep re-reads the deck for every value: the option must hold for each.
    const auto sweep = [](const std::string& formulation) {
      StudyRequest r = shippedDeckRequest("pump_rod.yaml");
      r.noSweep = false;
      r.sweep = "eta=0,0.2,0.4";
      r.formulation = formulation;
      return *solveStudy(r).sweep;
    };
    const SweepResult tims = sweep("timoshenko"), ebs = sweep("");
    for (std::size_t i = 0; i < tims.values.size(); ++i) {
      const double eta = tims.values[i];
      CAPTURE(eta);
      const ShearReactions tim = deckReactions(tims.runs[i]), eb = deckReactions(ebs.runs[i]);
      const ShearReactions timRef = closedForm(eta, 0.001, true),
                           ebRef = closedForm(eta, 0.001, false);
      double worst = 0;
      for (int k = 0; k < 5; ++k) {
        CAPTURE(k);
        CHECK(relError(tim[k], timRef[k]) < kTimoshenkoExact);
        CHECK(relError(eb[k], ebRef[k]) < kTimoshenkoExact);
        worst = std::max(worst, relError(tim[k], timRef[k]));
      }
      MESSAGE("eta = " << eta << ": Timoshenko against its closed form, largest rel. error "
                       << worst);
      // Shear flexibility softens the rod, and here every reaction drops: by 2 to 7 %, of the
      // order of Timoshenko's 12 EI / (kappa G A c^2) = 0.063 for the shortest span, c = 0.415
      // at eta = 0 (the rod is only 6 diameters long between the seal and the piston).
      const Eigen::Array<double, 5, 1> change = (tim.array() - eb.array()) / eb.array();
      MESSAGE("eta = " << eta << ": Timoshenko / EB - 1 = " << change.transpose());
      CHECK((change < 0).all());
    }
  }

  TEST_CASE(
      "the option on the command line: applied to any deck; bad or contradictory options exit 2") {
    const ProcessResult ok = runBeamrotor({"check", "problems/pump_rod_hinged.yaml", "--no-sweep",
                                           "--formulation", "euler-bernoulli"});
    CHECK(ok.exitCode == 0);
    // pump_rod.yaml's closed forms (and the paper's figures) are Euler-Bernoulli: with shear
    // they fail, and `check` says so (exit 3).
    const ProcessResult tim =
        runBeamrotor({"check", "problems/pump_rod.yaml", "--formulation", "timoshenko"});
    CHECK(tim.exitCode == 3);
    CHECK(tim.out.find("formulation: timoshenko for every segment") != std::string::npos);
    CHECK(tim.out.find("FAIL  left moment closed form") != std::string::npos);
    const ProcessResult bad =
        runBeamrotor({"solve", "problems/pump_rod.yaml", "--formulation", "timoshenk"});
    CHECK(bad.exitCode == 2);
    CHECK(bad.err.find("problems/pump_rod.yaml: --formulation timoshenk: expected") == 0);
    CHECK(bad.err.find("did you mean 'timoshenko'") != std::string::npos);
    CHECK(bad.err.find('\n') == bad.err.size() - 1);
    // Contradictory options are refused rather than one silently winning.
    const ProcessResult both =
        runBeamrotor({"check", "problems/pump_rod.yaml", "--no-sweep", "--sweep", "eta=0,0.4"});
    CHECK(both.exitCode == 2);
    CHECK(both.err.find("problems/pump_rod.yaml: --no-sweep: contradicts --sweep eta=0,0.4") == 0);
  }
}

// Response-spectrum analysis against closed forms: a single oscillator, a two-storey shear
// frame's modal solution, Der Kiureghian's CQC against SRSS for well-separated modes, the
// EN 1998-1:2004 elastic spectrum at its corner periods, and the 100/30 % rule.
#include <doctest/doctest.h>

#include <cmath>
#include <numbers>

#include "elements/PointInertia.hpp"
#include "elements/Spring.hpp"
#include "fem/modal/ResponseSpectrum.hpp"
#include "tests/Helpers.hpp"

using namespace beamrotor;
using namespace beamrotor::test;

namespace {

/// A shear building along ux: ground node 0 (supported), storeys 1..n with masses m[i] joined
/// by storey springs k[i] (k[0] between the ground and storey 1).
Model shearBuilding(const std::vector<double>& m, const std::vector<double>& k) {
  Model model;
  const int ground = model.addNode({0, 0, 0});
  model.addSupport({"base", ground, {{Dof::ux, 0}}});
  int below = ground;
  for (std::size_t i = 0; i < m.size(); ++i) {
    const int storey = model.addNode({0, 3.0 * double(i + 1), 0});
    model.nameNode("storey" + std::to_string(i + 1), storey);
    model.addElement(std::make_unique<PointInertia>(storey, DofSet{Dof::ux}, m[i]));
    model.addElement(std::make_unique<Spring>(NodeDof{below, Dof::ux}, NodeDof{storey, Dof::ux},
                                              k[i]));
    below = storey;
  }
  return model;
}

/// A straight table Sa = a - b T over 0..20 s: any period of these models reads it exactly.
DesignSpectrum sloped(double a, double b) { return DesignSpectrum::table({0, 20}, {a, a - 20 * b}); }

ResponseSpectrumOptions onlyX(int modes, ModalRule rule) {
  ResponseSpectrumOptions o;
  o.modes = modes;
  o.rule = rule;
  o.directions = {0};
  return o;
}

}  // namespace

TEST_SUITE("response spectrum") {
  TEST_CASE("a mass on a column: its spectral displacement, base shear m Sa, all of the mass") {
    const double m = 1200, k = 4.7e6;
    const Model model = shearBuilding({m}, {k});
    const DesignSpectrum spectrum = DesignSpectrum::en1998(1, GroundType::C, 3.0, 0.05);
    const ResponseSpectrumResult r = solveResponseSpectrum(model, spectrum, onlyX(1, ModalRule::cqc));
    const double w2 = k / m, T = 2 * kPi / std::sqrt(w2);
    // T = 0.1 s lies on the rising branch (TB = 0.2 s for ground C): Sa by (3.2) by hand,
    // S = 1.15, eta = 1.
    const double Sa = 3.0 * 1.15 * (1 + T / 0.2 * (2.5 - 1));
    REQUIRE(r.modal.modes.size() == 1);
    // One eigenpair of a 1x1 system and a few products: round-off.
    CHECK(relError(r.spectralAcceleration[0], Sa) < 1e-12);
    CHECK(relError(r.combined.displacement(1, 0), Sa / w2) < 1e-12);
    CHECK(relError(r.combined.reactions.at(0).value, m * Sa) < 1e-12);
    CHECK(relError(r.combined.baseForce[0], m * Sa) < 1e-12);
    CHECK(relError(r.modal.modes[0].effectiveMass[0], m) < 1e-12);
    CHECK(relError(r.capturedFraction()[0], 1.0) < 1e-12);
    CHECK(r.warnings.empty());
  }

  TEST_CASE("two-storey shear frame against its closed-form modal solution") {
    const double m1 = 2.0e4, m2 = 1.5e4, k1 = 3.2e7, k2 = 2.4e7, xi = 0.05;
    const Model model = shearBuilding({m1, m2}, {k1, k2});
    const DesignSpectrum spectrum = sloped(6.0, 2.0);
    // Closed form: det(K - lambda M) = 0 for K = [k1+k2, -k2; -k2, k2], M = diag(m1, m2) is
    // m1 m2 lambda^2 - (m1 k2 + m2 (k1 + k2)) lambda + k1 k2 = 0; a mode's storey ratio is
    // a = (k1 + k2 - m1 lambda) / k2, normalised by 1/sqrt(m1 + m2 a^2); Gamma = (m1 + m2 a) phi1.
    const double A = m1 * m2, B = -(m1 * k2 + m2 * (k1 + k2)), C = k1 * k2;
    const double disc = std::sqrt(B * B - 4 * A * C);
    const double lambda[2] = {(-B - disc) / (2 * A), (-B + disc) / (2 * A)};
    double phi[2][2], gamma[2], Sa[2];
    for (int j = 0; j < 2; ++j) {
      const double a = (k1 + k2 - m1 * lambda[j]) / k2, n = 1 / std::sqrt(m1 + m2 * a * a);
      phi[j][0] = n;
      phi[j][1] = a * n;
      gamma[j] = (m1 + m2 * a) * n;
      Sa[j] = 6.0 - 2.0 * 2 * kPi / std::sqrt(lambda[j]);
    }
    for (ModalRule rule : {ModalRule::srss, ModalRule::cqc}) {
      CAPTURE(int(rule));
      ResponseSpectrumOptions o = onlyX(2, rule);
      o.dampingRatio = xi;
      const ResponseSpectrumResult r = solveResponseSpectrum(model, spectrum, o);
      REQUIRE(r.modal.modes.size() == 2);
      const double rho = rule == ModalRule::cqc
                             ? cqcCorrelation(std::sqrt(lambda[0]), std::sqrt(lambda[1]), xi)
                             : 0;
      // A 2x2 eigenproblem solved by Lanczos to round-off; everything after is products.
      const auto combined = [&](double q0, double q1) {
        return std::sqrt(q0 * q0 + q1 * q1 + 2 * rho * q0 * q1);
      };
      double massSum = 0;
      for (int j = 0; j < 2; ++j) {
        const Mode& mode = r.modal.modes[j];
        CHECK(relError(mode.eigenvalue, lambda[j]) < 1e-10);
        CHECK(relError(std::abs(mode.participation[0]), std::abs(gamma[j])) < 1e-10);
        CHECK(relError(mode.effectiveMass[0], gamma[j] * gamma[j]) < 1e-10);
        massSum += mode.effectiveMass[0];
      }
      CHECK(relError(massSum, m1 + m2) < 1e-12);
      for (int storey = 0; storey < 2; ++storey) {
        double q[2];
        for (int j = 0; j < 2; ++j) q[j] = phi[j][storey] * gamma[j] * Sa[j] / lambda[j];
        CHECK(relError(r.combined.displacement(storey + 1, 0), combined(q[0], q[1])) < 1e-10);
      }
      // Base shear: Gamma_j^2 Sa_j per mode, combined; the support's reaction is the same
      // quantity through the first storey's spring, k1 u1 per mode.
      const double shear = combined(gamma[0] * gamma[0] * Sa[0], gamma[1] * gamma[1] * Sa[1]);
      CHECK(relError(r.combined.baseForce[0], shear) < 1e-10);
      CHECK(relError(r.combined.reactions.at(0).value, shear) < 1e-10);
    }
  }

  TEST_CASE("CQC equals SRSS plus the cross terms Der Kiureghian's rho gives; small apart") {
    // Storeys far apart in frequency: w2 / w1 = 2.6 for equal storeys, rho12 ~ 0.009 at 5 %.
    const Model model = shearBuilding({1e4, 1e4}, {2e7, 2e7});
    const DesignSpectrum spectrum = sloped(8.0, 1.0);
    const ResponseSpectrumResult srss = solveResponseSpectrum(model, spectrum, onlyX(2, ModalRule::srss));
    const ResponseSpectrumResult cqc = solveResponseSpectrum(model, spectrum, onlyX(2, ModalRule::cqc));
    const double rho = cqc.correlation(0, 1);
    // Equal storeys: lambda = (k/m)(3 -+ sqrt 5)/2, so w2/w1 is the golden ratio squared.
    const double r = std::pow((1 + std::sqrt(5.0)) / 2, 2);
    CHECK(relError(std::sqrt(cqc.modal.modes[1].eigenvalue / cqc.modal.modes[0].eigenvalue), r) <
          1e-10);
    CHECK(relError(rho, 8 * 0.0025 * (1 + r) * std::pow(r, 1.5) /
                            (std::pow(1 - r * r, 2) + 4 * 0.0025 * r * (1 + r) * (1 + r))) < 1e-14);
    CHECK(rho < 0.01);
    // Each storey: CQC^2 - SRSS^2 = 2 rho q1 q2 with q_j the modal values (round-off), and
    // so the two rules differ by less than rho relative to SRSS.
    for (int storey = 1; storey <= 2; ++storey) {
      double q[2];
      for (int j = 0; j < 2; ++j) {
        const Mode& mode = cqc.modal.modes[j];
        q[j] = mode.shape(storey, 0) * mode.participation[0] * cqc.spectralAcceleration[j] /
               mode.eigenvalue;
      }
      const double a = cqc.combined.displacement(storey, 0), b = srss.combined.displacement(storey, 0);
      CHECK(std::abs((a * a - b * b) - 2 * rho * q[0] * q[1]) < 1e-12 * b * b);
      CHECK(std::abs(a - b) / b < rho);
    }
  }

  TEST_CASE("CQC of two modes at one frequency adds them as one; SRSS does not") {
    CHECK(cqcCorrelation(10, 10, 0.05) == doctest::Approx(1).epsilon(1e-15));
    const Eigen::MatrixXd q = (Eigen::MatrixXd(1, 2) << 3.0, 4.0).finished();
    CHECK(combineModes(q, modalCorrelations({10, 10}, 0.05, ModalRule::cqc))[0] ==
          doctest::Approx(7).epsilon(1e-15));
    CHECK(combineModes(q, modalCorrelations({10, 10}, 0.05, ModalRule::srss))[0] ==
          doctest::Approx(5).epsilon(1e-15));
  }

  TEST_CASE("100/30 % and SRSS of the directions by hand") {
    const Eigen::MatrixXd peaks = (Eigen::MatrixXd(2, 2) << 10.0, 4.0, 1.0, 2.0).finished();
    const Eigen::VectorXd p = combineDirections(peaks, DirectionalRule::percent30);
    CHECK(p[0] == doctest::Approx(10 + 0.3 * 4).epsilon(1e-15));
    CHECK(p[1] == doctest::Approx(2 + 0.3 * 1).epsilon(1e-15));
    const Eigen::VectorXd s = combineDirections(peaks, DirectionalRule::srss);
    CHECK(s[0] == doctest::Approx(std::sqrt(116.0)).epsilon(1e-15));
  }

  TEST_CASE("EN 1998-1 elastic spectrum at its corner periods against hand values") {
    // Type 1, ground B: S = 1.2, TB = 0.15, TC = 0.5, TD = 2 s (Table 3.2); ag = 2.5 m/s^2.
    const DesignSpectrum b = DesignSpectrum::en1998(1, GroundType::B, 2.5, 0.05);
    CHECK(b.at(0) == doctest::Approx(3.0).epsilon(1e-14));      // ag S
    CHECK(b.at(0.15) == doctest::Approx(7.5).epsilon(1e-14));   // 2.5 ag S eta
    CHECK(b.at(0.5) == doctest::Approx(7.5).epsilon(1e-14));
    CHECK(b.at(2.0) == doctest::Approx(1.875).epsilon(1e-14));  // 7.5 TC / TD
    CHECK(b.at(4.0) == doctest::Approx(0.46875).epsilon(1e-14));  // 7.5 TC TD / 16
    CHECK(b.at(0.075) == doctest::Approx(5.25).epsilon(1e-14));   // halfway up the ramp
    // Type 2, ground D: S = 1.8, TB = 0.1, TC = 0.3, TD = 1.2 s (Table 3.3); ag = 1 m/s^2.
    const DesignSpectrum d = DesignSpectrum::en1998(2, GroundType::D, 1.0, 0.05);
    CHECK(d.at(0.2) == doctest::Approx(4.5).epsilon(1e-14));
    CHECK(d.at(1.2) == doctest::Approx(4.5 * 0.3 / 1.2).epsilon(1e-14));
    // Damping correction (3.6): 2 % gives sqrt(10/7); 30 % stops at 0.55.
    CHECK(en1998DampingCorrection(0.02) == doctest::Approx(std::sqrt(10.0 / 7)).epsilon(1e-15));
    CHECK(en1998DampingCorrection(0.30) == 0.55);
    CHECK(DesignSpectrum::en1998(1, GroundType::B, 2.5, 0.02).at(0.3) ==
          doctest::Approx(7.5 * std::sqrt(10.0 / 7)).epsilon(1e-14));
  }

  TEST_CASE("EN 1998-1 vertical spectrum: Table 3.4 and (3.8)-(3.11) by hand") {
    // Type 1, ag = 2 m/s^2: avg = 0.9 ag = 1.8, TB = 0.05, TC = 0.15, TD = 1 s, plateau
    // 3.0 avg = 5.4 at 5 % (eta = 1), whatever the ground.
    const DesignSpectrum v1 = DesignSpectrum::en1998Vertical(1, 2.0, 0.05);
    CHECK(v1.at(0) == doctest::Approx(1.8).epsilon(1e-14));
    CHECK(v1.at(0.025) == doctest::Approx(1.8 * (1 + 0.5 * 2)).epsilon(1e-14));
    CHECK(v1.at(0.1) == doctest::Approx(5.4).epsilon(1e-14));
    CHECK(v1.at(1.0) == doctest::Approx(5.4 * 0.15).epsilon(1e-14));
    CHECK(v1.at(2.0) == doctest::Approx(5.4 * 0.15 * 1.0 / 4).epsilon(1e-14));
    // Type 2: avg = 0.45 ag; at 2 % damping eta = sqrt(10 / 7) on the plateau.
    const DesignSpectrum v2 = DesignSpectrum::en1998Vertical(2, 2.0, 0.02);
    CHECK(v2.at(0.1) == doctest::Approx(0.9 * 3 * std::sqrt(10.0 / 7)).epsilon(1e-14));
    CHECK(v2.describe().find("vertical") != std::string::npos);
  }

  TEST_CASE("a period outside the table holds its end value; a direction without mass") {
    const Model model = shearBuilding({1000}, {1e6});  // T = 0.199 s
    // Below the table's first period the first value holds, above its last the last; each
    // such mode is named in a warning. The table's values are exact (no interpolation).
    const ResponseSpectrumResult below = solveResponseSpectrum(
        model, DesignSpectrum::table({0.5, 1}, {2, 3}), onlyX(1, ModalRule::cqc));
    CHECK(below.spectralAcceleration.front() == 2.0);
    REQUIRE(below.warnings.size() == 1);
    CHECK(below.warnings.front().find("mode 1 has the period 0.198") != std::string::npos);
    const ResponseSpectrumResult above = solveResponseSpectrum(
        model, DesignSpectrum::table({0.05, 0.1}, {2, 3}), onlyX(1, ModalRule::cqc));
    CHECK(above.spectralAcceleration.front() == 3.0);
    CHECK(above.warnings.size() == 1);
    CHECK(solveResponseSpectrum(model, DesignSpectrum::table({0.1, 0.3}, {2, 3}),
                                onlyX(1, ModalRule::cqc))
              .warnings.empty());
    ResponseSpectrumOptions o = onlyX(1, ModalRule::cqc);
    o.directions = {1};
    CHECK_THROWS_AS(solveResponseSpectrum(model, sloped(1, 0), o), std::invalid_argument);
  }
}

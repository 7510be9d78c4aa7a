// Crank-slider drive (problems/scenes/README.md section 3): kinematics against finite differences
// and against the harmonic series, the published SNT-32 figures, the triplex balance and the
// pump-rod load source (problems/scenes/README.md section 1).
#include <doctest/doctest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <numbers>
#include <stdexcept>
#include <utility>
#include <vector>

#include "problems/scenes/CrankSlider.hpp"
#include "tests/Helpers.hpp"

using namespace beamrotor;
using beamrotor::test::kPi;
using namespace beamrotor::crank;
using beamrotor::test::relError;

namespace {

/// Half a unit of the last printed digit, relative: the published figure's own precision.
/// E.g. printed(1.17, 0.01) = 0.005 / 1.17.
double printed(double value, double unit) {
  return 0.5 * unit / value;
}

/// Largest |exact a - series a| / (r omega^2) over a revolution (dense sampling: the residual is
/// a trigonometric polynomial of order ~8 plus smaller terms; 4000 samples resolve its peak to
/// far better than the factor-of-two steps the rate test compares).
double seriesResidual(double lambda, bool flipA4 = false) {
  const Geometry g{lambda, 1.0};
  const SeriesCoefficients A = seriesCoefficients(lambda);
  double worst = 0;
  for (int i = 0; i <= 4000; ++i) {
    const double phi = i * 2 * kPi / 4000;
    const double series = std::cos(phi) + A.A2 * std::cos(2 * phi) +
                          (flipA4 ? +1 : -1) * A.A4 * std::cos(4 * phi) + A.A6 * std::cos(6 * phi);
    worst = std::max(worst, std::abs(exactInPhi(g, phi).d2x / g.r - series));
  }
  return worst;
}

}  // namespace

TEST_SUITE("crank slider") {
  TEST_CASE("exact kinematics: dead centres and the rod angle") {
    const Geometry g = makeGeometry(0.0188, 0.288);
    // x = 0 at the outer dead centre, 2 r at the inner one; beta = asin(lambda) at phi = pi/2.
    CHECK(exactInPhi(g, 0).x == doctest::Approx(0).epsilon(1e-15));
    CHECK(exactInPhi(g, kPi).x == doctest::Approx(2 * g.r).epsilon(1e-14));
    CHECK(exactInPhi(g, kPi / 2).beta == doctest::Approx(std::asin(g.lambda())).epsilon(1e-14));
    // At phi = pi/2 the slider is past mid-stroke by l (1 - cos beta) (the rod's obliquity).
    const double cb = std::sqrt(1 - g.lambda() * g.lambda());
    CHECK(exactInPhi(g, kPi / 2).x == doctest::Approx(g.r + g.l * (1 - cb)).epsilon(1e-13));
    // a(0) = r omega^2 (1 + lambda), a(pi) = -r omega^2 (1 - lambda): textbook dead-centre values.
    CHECK(exact(g, 0, 62).a == doctest::Approx(g.r * 62 * 62 * (1 + g.lambda())).epsilon(1e-14));
    CHECK(exact(g, kPi, 62).a == doctest::Approx(-g.r * 62 * 62 * (1 - g.lambda())).epsilon(1e-13));
    CHECK_THROWS_AS(makeGeometry(0.3, 0.2), std::invalid_argument);
    CHECK_THROWS_AS(makeGeometry(0.0, 0.2), std::invalid_argument);
  }

  TEST_CASE("exact kinematics: analytic rates against finite differences") {
    // Central differences in phi with h = 1e-4 rad: truncation h^2/6 |f'''| <~ 2e-9 of the scale
    // (f''' of x is bounded by ~ r (1 + 8 lambda) for these lambda), round-off ~ eps / h ~ 2e-12.
    // Tolerance 1e-8 of r omega^k (or lambda omega^k for the rod) sits between the two.
    const double h = 1e-4, tol = 1e-8, omega = 62;
    for (const Geometry g : {Geometry{0.0188, 0.288}, Geometry{0.2, 0.6}}) {
      const double lam = g.lambda();
      for (int i = 0; i < 48; ++i) {
        const double phi = 0.1 + i * 2 * kPi / 48;
        const State s = exact(g, phi, omega);
        const State p = exact(g, phi + h, omega), m = exact(g, phi - h, omega);
        CAPTURE(lam);
        CAPTURE(phi);
        CHECK(std::abs((p.x - m.x) / (2 * h) * omega - s.v) <= tol * g.r * omega);
        CHECK(std::abs((p.v - m.v) / (2 * h) * omega - s.a) <= tol * g.r * omega * omega);
        CHECK(std::abs((p.beta - m.beta) / (2 * h) * omega - s.betaDot) <= tol * lam * omega);
        CHECK(std::abs((p.betaDot - m.betaDot) / (2 * h) * omega - s.betaDDot) <=
              tol * lam * omega * omega);
        // The closed forms quoted in the brief: omega lambda cos phi / cos beta and
        // v = r omega sin(phi + beta) / cos beta.
        CHECK(s.betaDot ==
              doctest::Approx(omega * lam * std::cos(phi) / std::cos(s.beta)).epsilon(1e-13));
        CHECK(s.v == doctest::Approx(g.r * omega * std::sin(phi + s.beta) / std::cos(s.beta))
                         .epsilon(1e-12)
                         .scale(g.r * omega));
      }
    }
  }

  TEST_CASE("exact kinematics: a non-uniformly turning crank") {
    // phi(t) = phi0 + omega0 t + alpha t^2/2; the state at t uses omega(t) = omega0 + alpha t.
    // Differencing v(t) and betaDot(t) in time checks the alpha terms of the chain rule.
    // h = 3e-6 s: truncation h^2/6 |jerk| ~ 1.5e-12 s^2 * 6e3 m/s^3 ~ 1e-8 m/s^2, round-off
    // eps v / h ~ 1e-10 m/s^2; 1e-8 of r omega^2 (~ 7e-7 m/s^2) bounds both.
    const Geometry g{0.0188, 0.288};
    const double phi0 = 0.7, omega0 = 62, alpha = 500, h = 3e-6;
    auto at = [&](double t) {
      return exact(g, phi0 + omega0 * t + alpha * t * t / 2, omega0 + alpha * t, alpha);
    };
    for (double t : {0.0, 0.01, 0.033}) {
      const State s = at(t), p = at(t + h), m = at(t - h);
      const double w = omega0 + alpha * t;
      CHECK(std::abs((p.v - m.v) / (2 * h) - s.a) <= 1e-8 * g.r * w * w);
      CHECK(std::abs((p.betaDot - m.betaDot) / (2 * h) - s.betaDDot) <= 1e-8 * g.lambda() * w * w);
    }
  }

  TEST_CASE("harmonic series: signs and the lambda^7 residual") {
    // At phi = 0 the series sums to 1 + lambda exactly (the lambda^5 terms 15/128 - 24/128 +
    // 9/128 cancel), the exact dead-centre value: agreement to round-off.
    for (double lam : {0.065, 0.2, 0.4}) {
      CHECK(evaluate(accelerationHarmonics(lam), 0) == doctest::Approx(1 + lam).epsilon(1e-15));
    }
    // The residual of the series through lambda^5 must fall like lambda^7: halving lambda divides
    // it by ~2^7 = 128. The leading coefficient tends to 5/16 (measured 0.324, 0.315, 0.313 at
    // lambda = 0.2, 0.1, 0.05), so the rates are 7 + O(lambda^2): within 0.2 of 7 here. At
    // lambda = 0.05 the residual is 2.4e-10, far above round-off (~1e-16).
    const std::vector<double> lambdas{0.2, 0.1, 0.05};
    std::vector<double> res;
    for (double lam : lambdas) res.push_back(seriesResidual(lam));
    for (std::size_t i = 0; i < res.size(); ++i) {
      CAPTURE(lambdas[i]);
      CHECK(relError(res[i] / std::pow(lambdas[i], 7), 0.3125) < 0.05);
      if (i > 0) CHECK(std::log2(res[i - 1] / res[i]) == doctest::Approx(7).epsilon(0.2 / 7));
    }
    // The paper's lambda: residual 1.5e-9 of r omega^2, i.e. 1e-7 m/s^2 on 77 m/s^2.
    CHECK(seriesResidual(0.065) < 0.33 * std::pow(0.065, 7));
    // The sign of the cos 4 phi term matters: with +A4 the residual is 2 A4 ~ lambda^3 / 2, only
    // third order (5e-4 at lambda = 0.1 against 3e-8 with the derived sign); the lambda^7
    // residual on top is 6.3e-5 of it (measured), so 2e-4.
    CHECK(relError(seriesResidual(0.1, true), 2 * seriesCoefficients(0.1).A4) < 2e-4);
    // The two-term forms drop the lambda^3 terms (x: l (1 - cos beta) = r (lambda s/2 +
    // lambda^3 s^2/8 + ...), s = sin^2 phi): their residual falls like lambda^3, ratio 2^3.
    auto twoTermResidual = [](double lam) {
      const Geometry g{lam, 1.0};
      double worst = 0;
      for (int i = 0; i <= 2000; ++i) {
        const double phi = i * 2 * kPi / 2000;
        worst = std::max(worst, std::abs(exact(g, phi, 1).a - approximate(g, phi, 1).a) / g.r);
      }
      return worst;
    };
    CHECK(std::log2(twoTermResidual(0.1) / twoTermResidual(0.05)) ==
          doctest::Approx(3).epsilon(0.05));
    // seriesAcceleration is the same series in m/s^2.
    const Geometry g{0.0188, 0.288};
    CHECK(seriesAcceleration(g, 0.3, 62) ==
          doctest::Approx(exact(g, 0.3, 62).a).epsilon(0.33 * std::pow(g.lambda(), 7)));
  }

  TEST_CASE("peaks over a revolution against closed forms") {
    // maxAcceleration by search must land on r omega^2 (1 + lambda) (round-off: the search is
    // flat at the maximum); the rod's amplitudes by dense sampling on omega lambda and
    // omega^2 lambda / sqrt(1 - lambda^2) (sampling every 0.05 deg loses ~ (4e-4)^2 relative at
    // a smooth peak, and both peaks sit on sample points 0 and pi/2 anyway).
    for (const Geometry g : {Geometry{0.0188, 0.288}, Geometry{0.2, 0.8}}) {
      const double w = 62, lam = g.lambda();
      CHECK(maxAcceleration(g, w) == doctest::Approx(g.r * w * w * (1 + lam)).epsilon(1e-14));
      double wMax = 0, eMax = 0, vMax = 0;
      for (int i = 0; i < 7200; ++i) {
        const State s = exact(g, i * 2 * kPi / 7200, w);
        wMax = std::max(wMax, std::abs(s.betaDot));
        eMax = std::max(eMax, std::abs(s.betaDDot));
        vMax = std::max(vMax, std::abs(s.v));
      }
      CHECK(wMax == doctest::Approx(rodAngularVelocityAmplitude(lam, w)).epsilon(1e-14));
      CHECK(eMax == doctest::Approx(rodAngularAccelerationAmplitude(lam, w)).epsilon(1e-14));
      // |v| is flat at its peak: a sample within 0.025 deg is within ~1e-7 relative, below it.
      CHECK(vMax <= maxVelocity(g, w) * (1 + 1e-15));
      CHECK(vMax == doctest::Approx(maxVelocity(g, w)).epsilon(1e-6));
    }
  }

  TEST_CASE("SNT-32 published figures") {
    // Readings. The paper rounds omega to 62 rad/s (588 rpm is 61.575 rad/s) and lambda to
    // 0.065 (r/l = 0.06528). Each figure is asserted to half a unit of its last printed digit,
    // relative, under the reading that reproduces it; where that reading is the only one, the
    // competing readings are shown to miss. Where no reading reproduces a figure, what we compute
    // is asserted against its closed form evaluated here from the paper's data (r = 0.0188 m,
    // l = 0.288 m, 62 rad/s or 588 rpm, three 45 mm plungers) and the discrepancy is recorded.
    const Snt32 pump;
    const Geometry& g = pump.geometry;
    const double w62 = pump.printedOmega;  // 62 rad/s
    const double w588 = pump.omega();      // 61.575 rad/s
    const double lamPrinted = pump.printedLambda, lam = g.lambda();
    CHECK(w588 == doctest::Approx(61.575216010).epsilon(1e-10));
    CHECK(lam == doctest::Approx(0.0652777778).epsilon(1e-9));

    SUBCASE("v_max = 1.17 m/s: exact maximum at omega = 62") {
      // 1.16808 (+0.16 %); at 588 rpm it would be 1.16008 (-0.85 %, outside the print).
      CHECK(relError(maxVelocity(g, w62), 1.17) <= printed(1.17, 0.01));
      CHECK(relError(maxVelocity(g, w588), 1.17) > printed(1.17, 0.01));
    }
    SUBCASE("a_max = 74.75 m/s^2: DISCREPANCY, no consistent reading") {
      // The exact maximum is r omega^2 (1 + lambda) at the outer dead centre: 76.985 at
      // omega = 62 (+3.0 % over the print), 75.93 at 588 rpm (+1.6 %); the first harmonic alone
      // r omega^2 = 72.27 (-3.3 %); even r omega^2 (1 + lambda/2) = 74.63 (-0.17 %) misses the
      // printed precision (0.007 %). Reproducing 74.75 needs other inputs (e.g. r = 18.5 mm at
      // 588 rpm), which we do not use. Asserted: what we compute, against r omega^2 (1 + r / l)
      // (the search lands on the flat maximum to round-off, as in the peaks test).
      const double aMax = maxAcceleration(g, w62);
      const double rpm588 = 588 * 2 * kPi / 60;
      CHECK(relError(aMax, 0.0188 * 62 * 62 * (1 + 0.0188 / 0.288)) < 1e-14);
      CHECK(relError(maxAcceleration(g, w588), 0.0188 * rpm588 * rpm588 * (1 + 0.0188 / 0.288)) <
            1e-14);
      for (double candidate : {aMax, maxAcceleration(g, w588), g.r * w62 * w62,
                               g.r * w62 * w62 * (1 + lam / 2), g.r * w588 * w588 * (1 + lam)})
        CHECK(relError(candidate, 74.75) > printed(74.75, 0.01));
      MESSAGE("a_max: computed " << aMax << " m/s^2 vs published 74.75, rel. error "
                                 << relError(aMax, 74.75));
    }
    SUBCASE("v_max / v_mean = 1.57: exact, independent of omega") {
      // (pi/2)(1 + ~lambda^2/2) = 1.5741, +0.26 % within the print's 0.32 %.
      const double ratio = maxVelocity(g, w62) / meanSliderSpeed(g, w62);
      CHECK(relError(ratio, 1.57) <= printed(1.57, 0.01));
      CHECK(maxVelocity(g, w588) / meanSliderSpeed(g, w588) == doctest::Approx(ratio));
    }
    SUBCASE("mean slider speed 0.745 m/s: DISCREPANCY, derived from rounded figures") {
      // 2 r omega / pi = 0.74204 at omega = 62 (-0.40 %), 0.73696 at 588 rpm (-1.08 %); the print
      // allows 0.067 %. The paper's 0.745 is what the ROUNDED v_max gives: 1.17 / (pi/2) = 0.7448
      // (or 1.17 / 1.57 = 0.7452), not a reading of the data. Asserted: what we compute, against
      // the stroke 2 r covered twice a revolution, 2 (2 r) / (2 pi / omega) = 2 r omega / pi.
      const double vMean = meanSliderSpeed(g, w62);
      CHECK(relError(vMean, 2 * 0.0188 * 62 / kPi) < 1e-14);
      CHECK(relError(vMean, 0.745) > printed(0.745, 0.001));
      CHECK(relError(meanSliderSpeed(g, w588), 0.745) > printed(0.745, 0.001));
      CHECK(relError(1.17 / (kPi / 2), 0.745) <= printed(0.745, 0.001));  // the paper's chain
      MESSAGE("v_mean: computed " << vMean << " m/s vs published 0.745, rel. error "
                                  << relError(vMean, 0.745));
    }
    SUBCASE("rod angular velocity amplitude 4.03 1/s: omega lambda with the printed lambda") {
      // omega lambda is exact (peak at the dead centres). 62 * 0.065 = 4.030; with r/l it is
      // 4.047 (+0.43 %), at 588 rpm and r/l 4.0195 (-0.26 %): both outside the print (0.012 %).
      CHECK(relError(rodAngularVelocityAmplitude(lamPrinted, w62), 4.03) <= printed(4.03, 0.01));
      CHECK(relError(rodAngularVelocityAmplitude(lam, w62), 4.03) > printed(4.03, 0.01));
      CHECK(relError(rodAngularVelocityAmplitude(lam, w588), 4.03) > printed(4.03, 0.01));
    }
    SUBCASE("rod angular acceleration amplitude 249.9 1/s^2: first order, printed lambda") {
      // 62^2 * 0.065 = 249.86 (-0.016 %, print 0.020 %). The exact amplitude
      // omega^2 lambda / sqrt(1 - lambda^2) is 250.39 with the printed lambda (+0.20 %) and
      // 250.91 with r/l (+0.40 %): the paper used the first-order amplitude.
      CHECK(relError(rodAngularAccelerationAmplitudeFirstOrder(lamPrinted, w62), 249.9) <=
            printed(249.9, 0.1));
      CHECK(relError(rodAngularAccelerationAmplitude(lamPrinted, w62), 249.9) >
            printed(249.9, 0.1));
      CHECK(relError(rodAngularAccelerationAmplitude(lam, w62), 249.9) > printed(249.9, 0.1));
    }
    const ReducedMasses m = reduce(pump.masses, g);
    SUBCASE("reduced rotating 25.27 kg and reciprocating 17.79 kg: CoM 0.040 m from the big end") {
      // 24.1 * 7.62e-3 / 0.0188 = 9.768 at the pin + 18 * 0.248 / 0.288 = 15.5 of the rod = 25.268;
      // 15.29 + 18 * 0.040 / 0.288 = 2.5 -> 17.79. Swapping the ends gives 12.27 / 30.79.
      CHECK(m.rodBigEnd == doctest::Approx(15.5).epsilon(1e-14));
      CHECK(m.rodSmallEnd == doctest::Approx(2.5).epsilon(1e-14));
      CHECK(relError(m.rotating, 25.27) <= printed(25.27, 0.01));
      CHECK(relError(m.reciprocating, 17.79) <= printed(17.79, 0.01));
      DriveMasses swapped = pump.masses;
      std::swap(swapped.rod.comToBigEnd, swapped.rod.comToSmallEnd);
      CHECK(relError(reduce(swapped, g).rotating, 25.27) > 0.4);
    }
    SUBCASE("inertia force harmonics 1286 N and 84 N at omega = 62") {
      // m_rec r omega^2 = 17.79 * 0.0188 * 62^2 = 1285.6 (-0.03 %, print 0.039 %); at 588 rpm
      // 1268.0 (-1.4 %). Second: m_rec r omega^2 A2 = 84.01 with r/l (first order with the
      // printed lambda 83.57): both within the print's 0.6 %.
      const std::array<crank::Harmonic, 4> f =
          reciprocatingInertiaHarmonics(m.reciprocating, g, w62);
      CHECK(f[0].k == 1);
      CHECK(f[1].k == 2);
      CHECK(f[0].c < 0);  // the inertia force opposes the acceleration
      CHECK(relError(std::abs(f[0].c), 1286) <= printed(1286, 1));
      CHECK(relError(std::abs(f[1].c), 84) <= printed(84, 1));
      CHECK(relError(std::abs(f[0].c) * lamPrinted, 84) <= printed(84, 1));
      CHECK(relError(std::abs(reciprocatingInertiaHarmonics(m.reciprocating, g, w588)[0].c), 1286) >
            printed(1286, 1));
    }
    SUBCASE("inertia moment amplitude 232 N m = residual inertia x first-order rod acceleration") {
      // M = Delta J * eps_max, Delta J = J_G - m a b = 0.93 kg m^2 as printed (the correction
      // couple of the two-mass rod). 0.93 * 249.86 = 232.37 (+0.16 %, print 0.22 %). With the
      // exact amplitude and r/l: 0.93 * 250.91 = 233.35 (+0.58 %), i.e. "233".
      const double dJ = pump.masses.rod.residualInertia;
      const double M = dJ * rodAngularAccelerationAmplitudeFirstOrder(lamPrinted, w62);
      CHECK(relError(M, 232) <= printed(232, 1));
      CHECK(relError(dJ * rodAngularAccelerationAmplitude(lam, w62), 232) > printed(232, 1));
      // The couple as a function of the crank angle peaks at phi = pi/2 with the exact amplitude.
      CHECK(std::abs(rodCorrectionCouple(dJ, g, kPi / 2, w62)) ==
            doctest::Approx(dJ * rodAngularAccelerationAmplitude(lam, w62)).epsilon(1e-14));
      // Observation, not a reading: m b (b - a) = 18 * 0.248 * 0.208 = 0.9285 ~ 0.93, which is
      // J_G - m a b if J_G were m b^2 (the rod's mass as a point at its centre, seen from the
      // small end); the rod's actual J_G is not given. Recorded so nobody takes 0.93 on trust.
      CHECK(residualInertia(18.0 * 0.248 * 0.248, 18.0, 0.040, 0.248) ==
            doctest::Approx(0.92851).epsilon(1e-5));
    }
    SUBCASE("theoretical delivery 105.4 L/min: DISCREPANCY of 0.08 %") {
      // Q = 3 (pi 0.045^2 / 4) (2 * 0.0188) 588 = 105.488 L/min (+0.083 %, print 0.047 %); at
      // omega = 62 (592.1 rpm) 106.22. The paper's 105.4 is reproduced by pi = 3.14 (105.434)
      // or by truncating 105.49: its arithmetic, not the data. Asserted: what we compute, against
      // plungers x area x stroke x revolutions per minute, in litres.
      const double perMinute = 60e3;  // m^3/s -> L/min
      const double Q =
          theoreticalDelivery(pump.plungers, pump.plungerDiameter, g.stroke(), w588) * perMinute;
      CHECK(relError(Q, 3 * (kPi * 0.045 * 0.045 / 4) * (2 * 0.0188) * 588 * 1e3) < 1e-14);
      CHECK(relError(Q, 105.4) > printed(105.4, 0.1));
      CHECK(relError(3 * 3.14 / 4 * 0.045 * 0.045 * 0.0376 * 588 * 1e3, 105.4) <=
            printed(105.4, 0.1));
      MESSAGE("delivery: computed " << Q << " L/min vs published 105.4, rel. error "
                                    << relError(Q, 105.4));
    }
  }

  TEST_CASE("three cranks at 120 deg: rotating and reciprocating balance") {
    const Snt32 pump;
    const Geometry& g = pump.geometry;
    const double w = pump.printedOmega;
    const ReducedMasses m = reduce(pump.masses, g);
    const double F = m.rotating * g.r * w * w;  // one crank's centrifugal force, ~1826 N
    // Three unit vectors 120 deg apart: each sum is a few additions of O(1) numbers, so zero to
    // ~1e-15 of F; 1e-13 leaves room without hiding a real residue (the smallest physical term
    // here, A6, is 1e-7 of F).
    for (int i = 0; i < 36; ++i) {
      const double phi = i * kPi / 18;
      for (int order : {1, 2, 4, 5}) {
        const auto s = rotatingVectorSum(F, phi, order);
        CAPTURE(order);
        CHECK(std::hypot(s[0], s[1]) <= 1e-13 * F);
      }
      for (int order : {3, 6}) {
        const auto s = rotatingVectorSum(F, phi, order);
        CHECK(std::hypot(s[0], s[1]) == doctest::Approx(3 * F).epsilon(1e-14));
      }
      // Parallel cylinders, exact kinematics: orders 1, 2, 4 cancel and the resultant is
      // -3 m_rec r omega^2 A6 cos 6 phi (0.2 N on 1286 N) up to the O(lambda^7) series residual.
      const double mr = m.reciprocating * g.r * w * w;
      const double sum = reciprocatingForceSum(m.reciprocating, g, phi, w);
      const double sixth = -3 * mr * seriesCoefficients(g.lambda()).A6 * std::cos(6 * phi);
      CHECK(std::abs(sum - sixth) <= 3 * 0.33 * std::pow(g.lambda(), 7) * mr);
      CHECK(std::abs(sum) <=
            3 * mr * (seriesCoefficients(g.lambda()).A6 + 0.33 * std::pow(g.lambda(), 7)));
    }
  }

  TEST_CASE("pump rod load source (problems/scenes/README.md section 1 stroke)") {
    // A 0.4 m stroke (r = 0.2) with a rod of 1.0 m (lambda = 0.2), a 250 kg reciprocating set.
    const PumpRodDrive d{0.2, 1.0};
    const double w = 6.0, mass = 250;
    CHECK(pumpRodLoad(d, 0, w, mass).eta == doctest::Approx(0.4).epsilon(1e-15));
    CHECK(pumpRodLoad(d, kPi, w, mass).eta == doctest::Approx(0).scale(1).epsilon(1e-15));
    const double lam = d.r / d.l;
    for (int i = 0; i < 72; ++i) {
      const double phi = i * 2 * kPi / 72;
      const PumpRodSample s = pumpRodLoad(d, phi, w, mass);
      CHECK(s.eta >= -1e-15);
      CHECK(s.eta <= 0.4 + 1e-15);
      // eta moves opposite to x (crank on the left): rates against the exact slider state.
      const State x = exact(Geometry{d.r, d.l}, phi, w);
      CHECK(s.etaDot == doctest::Approx(-x.v).scale(d.r * w).epsilon(1e-15));
      CHECK(s.etaDDot == doctest::Approx(-x.a).scale(d.r * w * w).epsilon(1e-15));
      // The cos(k omega t) forcing reproduces the exact inertia force -m eta'' to the series
      // residual, 0.324 lambda^7 m r omega^2 at lambda = 0.2 (measured in the series test).
      CHECK(std::abs(forceAt(s.forcing, w, phi / w) + mass * s.etaDDot) <=
            0.33 * std::pow(lam, 7) * mass * d.r * w * w);
    }
    // The inverse: the crank angle in [0, pi] at which the rod stands at eta. Near a dead centre
    // acos loses half the digits (eta is quadratic in phi there), so the round trip is checked
    // on eta, to round-off.
    for (double eta : {0.0, 0.01, 0.1, 0.2, 0.3, 0.39, 0.4}) {
      const double phi = crankAngleAtStroke(d, eta);
      CHECK(phi >= 0);
      CHECK(phi <= kPi);
      CHECK(pumpRodLoad(d, phi, w, mass).eta == doctest::Approx(eta).scale(0.4).epsilon(1e-14));
    }
    CHECK(crankAngleAtStroke(d, 0.4) == doctest::Approx(0).scale(1).epsilon(1e-7));
    CHECK(crankAngleAtStroke(d, 0.0) == doctest::Approx(kPi).epsilon(1e-7));
    // Mid-stroke is reached before phi = pi/2 from the extreme right (the rod's obliquity).
    CHECK(crankAngleAtStroke(d, 0.2) < kPi / 2);
    // The other orientation: eta = x, the extreme left is the outer dead centre.
    const PumpRodDrive right{0.2, 1.0, false};
    CHECK(pumpRodLoad(right, 0, w, mass).eta == doctest::Approx(0).scale(1).epsilon(1e-15));
    CHECK(pumpRodLoad(right, 1.0, w, mass).forcing[0].c ==
          doctest::Approx(-pumpRodLoad(d, 1.0, w, mass).forcing[0].c));
    CHECK(crankAngleAtStroke(right, 0.2) ==
          doctest::Approx(crankAngleAtStroke(d, 0.2)).epsilon(1e-14));
    // Invalid input names the problem.
    CHECK_THROWS_AS(pumpRodLoad(PumpRodDrive{0.2, 0.1}, 0, w, mass), std::invalid_argument);
    CHECK_THROWS_AS(pumpRodLoad(PumpRodDrive{}, 0, w, mass), std::invalid_argument);  // l unset
    CHECK_THROWS_AS(crankAngleAtStroke(d, 0.41), std::invalid_argument);
    DriveMasses bad = Snt32{}.masses;
    bad.rod.comToSmallEnd = 0.3;
    CHECK_THROWS_AS(reduce(bad, Snt32{}.geometry), std::invalid_argument);
  }
}

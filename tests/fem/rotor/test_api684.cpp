// The API 684 reading of an unbalance response against a single mode's closed form.
//
// A Jeffcott rotor (mass m, stiffness k, damping c, unbalance m e) whirls at the spin speed
// Omega with radius X = e r^2 / sqrt((1 - r^2)^2 + (2 zeta r)^2), r = Omega / omega_n. Its
// peak is at r_p^2 = 1 / (1 - 2 zeta^2), X_p = e / (2 zeta sqrt(1 - zeta^2)); the half-power
// points solve X^2 = X_p^2 / 2, a quadratic in u = r^2:
//   (X_p^2 - 2) u^2 + X_p^2 (4 zeta^2 - 2) u + X_p^2 = 0     (X_p in units of e),
// and AF = r_p / (r_2 - r_1), close to 1 / (2 zeta) for light damping.
#include <doctest/doctest.h>

#include <cmath>
#include <vector>

#include "fem/rotor/Api684.hpp"

using namespace beamrotor;

namespace {

struct SingleModeResponse {
  double wn = 500, zeta = 0.02;  // rad/s

  double amplitude(double w) const {  // per unit eccentricity
    const double r = w / wn;
    return r * r / std::sqrt(std::pow(1 - r * r, 2) + std::pow(2 * zeta * r, 2));
  }
  double peakSpeed() const { return wn / std::sqrt(1 - 2 * zeta * zeta); }
  double peakAmplitude() const { return 1 / (2 * zeta * std::sqrt(1 - zeta * zeta)); }
  double exactFactor() const {
    const double X2 = std::pow(peakAmplitude(), 2);
    const double a = X2 - 2, b = X2 * (4 * zeta * zeta - 2), c = X2;
    const double d = std::sqrt(b * b - 4 * a * c);
    const double r1 = std::sqrt((-b - d) / (2 * a)), r2 = std::sqrt((-b + d) / (2 * a));
    return (peakSpeed() / wn) / std::abs(r2 - r1);
  }
};

}  // namespace

TEST_SUITE("api 684") {
  TEST_CASE("half-power amplification factor of a single lightly damped mode") {
    const SingleModeResponse s;
    std::vector<double> speeds, amplitudes;
    const int steps = 2000;  // 0 to 2 omega_n: 40 samples across the half-power band 2 zeta wn
    for (int i = 0; i <= steps; ++i) {
      speeds.push_back(2 * s.wn * i / steps);
      amplitudes.push_back(s.amplitude(speeds.back()));
    }
    const auto peaks = readResponsePeaks(speeds, amplitudes, {0.5 * s.wn, 0.7 * s.wn});
    REQUIRE(peaks.size() == 1);
    const ResponsePeak& p = peaks[0];
    // The parabola through three samples 0.001 wn apart: its top errs by O(h^3) relative to the
    // peak's width (2 zeta wn), ~1e-5 of the speed at most.
    CHECK(p.speed == doctest::Approx(s.peakSpeed()).epsilon(1e-5));
    CHECK(p.amplitude == doctest::Approx(s.peakAmplitude()).epsilon(1e-4));
    REQUIRE(p.halfPowerFound);
    // Half-power points interpolated linearly between samples 1/40 of the band apart: the
    // curve's bending there moves them by ~(1/40)^2 / 8 of the band, 1e-4 of the AF.
    CHECK(p.amplificationFactor == doctest::Approx(s.exactFactor()).epsilon(1e-3));
    // 1 / (2 zeta) is the light-damping limit, off by O(zeta^2) (1.6e-3 here).
    CHECK(p.amplificationFactor == doctest::Approx(1 / (2 * s.zeta)).epsilon(3e-3));
    // AF ~ 25 above the operating range 0.5-0.7 wn: SM required 10 + 17 (1 - 1/(AF - 1.5)),
    // actual (Nc - 0.7 wn) / 0.7 wn = 42.9 %: passes.
    const double af = p.amplificationFactor;
    CHECK(p.requiredMargin == doctest::Approx(10 + 17 * (1 - 1 / (af - 1.5))));
    CHECK(p.actualMargin == doctest::Approx(100 * (p.speed - 0.7 * s.wn) / (0.7 * s.wn)));
    CHECK(p.pass);
    // The same critical inside the operating range fails; below a range starting at 1.1 wn
    // it needs 17 (1 - 1/(AF - 1.5)) = 16.3 % and has only 1 - 1/1.1 = 9.1 %.
    CHECK_FALSE(readResponsePeaks(speeds, amplitudes, {0.9 * s.wn, 1.1 * s.wn})[0].pass);
    const ResponsePeak below = readResponsePeaks(speeds, amplitudes, {1.1 * s.wn, 1.3 * s.wn})[0];
    CHECK(below.requiredMargin == doctest::Approx(17 * (1 - 1 / (af - 1.5))));
    CHECK_FALSE(below.pass);
  }

  TEST_CASE("a heavily damped mode needs no margin") {
    SingleModeResponse s;
    s.zeta = 0.3;  // AF ~ 1.7 < 2.5: critically damped in API's sense
    std::vector<double> speeds, amplitudes;
    for (int i = 0; i <= 4000; ++i) {
      speeds.push_back(4 * s.wn * i / 4000);
      amplitudes.push_back(s.amplitude(speeds.back()));
    }
    const auto peaks = readResponsePeaks(speeds, amplitudes, {0.9 * s.wn, 1.2 * s.wn});
    REQUIRE(peaks.size() == 1);
    CHECK(peaks[0].amplificationFactor < 2.5);
    CHECK(peaks[0].requiredMargin == 0);
    CHECK(peaks[0].pass);
  }

  TEST_CASE("required margins of API 617 at round amplification factors") {
    CHECK(requiredSeparationMargin(2.4, false) == 0);
    CHECK(requiredSeparationMargin(10, false) == doctest::Approx(17 * (1 - 1 / 8.5)));
    CHECK(requiredSeparationMargin(10, true) == doctest::Approx(10 + 17 * (1 - 1 / 8.5)));
    CHECK(requiredSeparationMargin(3.5, false) == doctest::Approx(8.5));
  }
}

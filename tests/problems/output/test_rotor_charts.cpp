// The pieces of the rotor charts against numbers worked out by hand: the phase of a response
// unwrapped as the tables write it (a two-mode closed form, and an undamped sign change with
// round-off), the shared line styles kept apart, the operating band's API 684 margins, and the
// orbit samples of circular forward and backward whirl.
#include <doctest/doctest.h>

#include <cmath>
#include <complex>
#include <set>
#include <string>
#include <vector>

#include "problems/output/files/ChartParts.hpp"
#include "problems/output/rotor/OperatingBand.hpp"
#include "problems/output/rotor/RotorOrbitChart.hpp"
#include "problems/output/rotor/UnwrappedPhase.hpp"
#include "tests/Helpers.hpp"

using namespace beamrotor;
using namespace beamrotor::test;

namespace {

/// (-180, 180] deg, as std::arg gives it.
double wrapped(double degrees) {
  double w = std::fmod(degrees + 180, 360);
  if (w <= 0) w += 360;
  return w - 180;
}

/// The unwrapped phases of unit responses at `phases` (deg, as std::arg gives them).
std::vector<double> unwrapped(const std::vector<double>& phases) {
  std::vector<std::complex<double>> values;
  for (double p : phases) values.push_back(std::polar(1.0, p * kPi / 180));
  return unwrappedPhases(values);
}

}  // namespace

TEST_SUITE("rotor charts") {
  TEST_CASE("phase: continuous through two damped resonances, an undamped sign change one lag") {
    // Two modes in series (r = omega / omega_i, omega_2 = 2 omega_1, zeta 0.05 each): the
    // response lags by the sum of the two modes' phase angles, 0 to -360 deg, which wraps
    // at -180 into +180.
    std::vector<double> phases, exact;
    for (int i = 0; i < 60; ++i) {
      const double r1 = 0.05 * i, r2 = r1 / 2;
      const double lag = std::atan2(0.1 * r1, 1 - r1 * r1) + std::atan2(0.1 * r2, 1 - r2 * r2);
      exact.push_back(-lag * 180 / kPi);
      phases.push_back(wrapped(exact.back()));
    }
    const std::vector<double> damped = unwrapped(phases);
    REQUIRE(damped.size() == exact.size());
    // (Once read back from gnuplot's 6 digits; round-off alone now.)
    for (std::size_t i = 0; i < exact.size(); ++i) CHECK(damped[i] == doctest::Approx(exact[i]).epsilon(1e-5).scale(1));
    // Undamped: 0 below resonance, a sign change above, where round-off puts the phase at
    // +180 or -180 from point to point: one lag of 180 deg, then flat.
    const std::vector<double> undamped =
        unwrapped({0, 0, 0, 180, -180, 179.99999999, -180, 180, 180, -179.99999999});
    REQUIRE(undamped.size() == 10);
    for (std::size_t i = 0; i < undamped.size(); ++i)
      CHECK(undamped[i] == doctest::Approx(i < 3 ? 0 : -180).epsilon(1e-6).scale(1));
  }

  TEST_CASE("line styles: distinct colours for ten curves, distinct pairs for thirty") {
    std::set<std::string> colours, styles;
    for (std::size_t i = 0; i < 10; ++i) colours.insert(colour(i));
    CHECK(colours.size() == 10);
    REQUIRE(distinctLineStyles() >= 8);
    for (std::size_t i = 0; i < distinctLineStyles(); ++i) styles.insert(lineStyle(i));
    CHECK(styles.size() == distinctLineStyles());
    // Neighbours differ in the dash too (readable in grey): the dash part after the colour.
    for (std::size_t i = 0; i + 1 < distinctLineStyles(); ++i) {
      const std::string a = lineStyle(i), b = lineStyle(i + 1);
      CHECK(a.substr(a.find("dashtype")) != b.substr(b.find("dashtype")));
    }
  }

  TEST_CASE("operating band: the largest API 617 margin on each side") {
    // 7000-9000 rpm. Below it a critical with zeta 0.02 (AF 25: 17 (1 - 1 / 23.5) %) and one
    // with zeta 0.1 (AF 5: 17 (1 - 1 / 3.5) %); above, an undamped one (AF unbounded: 10 + 17 %)
    // and a heavily damped one (AF 1.67 < 2.5: none).
    const double rpm = kPi / 30;
    std::vector<CriticalSpeed> critical(4);
    const double speeds[] = {5000, 6000, 12000, 9500}, zetas[] = {0.02, 0.1, 0, 0.3};
    for (int k = 0; k < 4; ++k) {
      critical[k].rpm = speeds[k];
      critical[k].speed = speeds[k] * rpm;
      critical[k].dampingRatio = zetas[k];
    }
    const OperatingBand band = bandOfCriticalSpeeds({7000 * rpm, 9000 * rpm}, critical);
    CHECK(band.minRpm == doctest::Approx(7000));
    CHECK(band.maxRpm == doctest::Approx(9000));
    CHECK(band.marginBelow == doctest::Approx(17 * (1 - 1 / 23.5)));
    CHECK(band.marginAbove == doctest::Approx(27));
    const BandCommands shading = operatingBandCommands(band);
    // The range and both margins shaded: 7000 (1 - 0.1628) = 5860 rpm, 9000 x 1.27 = 11430.
    CHECK(shading.setup.find("from first 7000, graph 0 to first 9000") != std::string::npos);
    CHECK(shading.setup.find("from first " + number(7000 * (1 - band.marginBelow / 100)) +
                             ", graph 0 to first 7000") != std::string::npos);
    CHECK(shading.setup.find("from first 9000, graph 0 to first 11430") != std::string::npos);
    CHECK(shading.titles.size() == 2);  // "operating range", "API margins"
    CHECK(operatingBandCommands(std::nullopt).setup.empty());
  }

  TEST_CASE("orbit samples: circular forward and backward whirl, largest orbit 1") {
    Model model;
    model.addNode({0.5, 0, 0});
    model.addNode({0.0, 0, 0});  // out of order: the table goes along x
    RotorModesResult r;
    RotorMode mode;
    mode.shape = ComplexNodalField::Zero(2, kDofKinds);
    // Node 0: uy = 2, uz = -2i: Re(2 e^{it}, -2i e^{it}) = 2 (cos t, sin t), forward, radius 2.
    // Node 1: uy = 1, uz = +1i: (cos t, -sin t), backward, radius 1.
    const std::complex<double> i(0, 1);
    mode.shape(0, dofIndex(Dof::uy)) = 2.0;
    mode.shape(0, dofIndex(Dof::uz)) = -2.0 * i;
    mode.shape(1, dofIndex(Dof::uy)) = 1.0;
    mode.shape(1, dofIndex(Dof::uz)) = i;
    r.modes.push_back(mode);
    const CsvTable t = modeOrbitsTable("orbits.csv", r, model);
    REQUIRE(t.rowCount() == 72);  // 36 angles x 2 nodes
    const auto x = t.numbers("x"), angle = t.numbers("angle"), uy = t.numbers("uy");
    const auto uz = t.numbers("uz"), duy = t.numbers("duy"), duz = t.numbers("duz");
    const auto whirl = t.numbers("whirl");
    for (std::size_t k = 0; k < t.rowCount(); ++k) {
      CAPTURE(k);
      const bool first = k % 2 == 0;  // x = 0 (node 1, backward) first, then x = 0.5
      CHECK(x[k] == (first ? 0.0 : 0.5));
      const double a = angle[k] * kPi / 180, radius = first ? 0.5 : 1.0;
      const double sense = first ? -1 : 1;
      // Scaled so that the largest orbit's semi-major axis is 1: round-off only.
      CHECK(uy[k] == doctest::Approx(radius * std::cos(a)).scale(1));
      CHECK(uz[k] == doctest::Approx(sense * radius * std::sin(a)).scale(1));
      const double b = a + 2 * kPi / 36;
      CHECK(uy[k] + duy[k] == doctest::Approx(radius * std::cos(b)).scale(1));
      CHECK(uz[k] + duz[k] == doctest::Approx(sense * radius * std::sin(b)).scale(1));
      CHECK(whirl[k] == sense);
    }
  }
}

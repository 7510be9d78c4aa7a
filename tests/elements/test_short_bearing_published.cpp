// The short (Ocvirk) plain journal bearing against published numbers: the worked example of
// Friswell, Penny, Garvey and Lees, Dynamics of Rotating Machines (Cambridge 2010), Example
// 5.5.1, and the classical short-bearing stability chart of a rigid rotor (oil whip): the
// eccentricity ratio above which a rigid rotor in short plain bearings is stable at every speed,
// and the onset speed found by the rotor eigensolver against the stability threshold written
// from the eight coefficients.
#include <doctest/doctest.h>

#include <array>
#include <cmath>
#include <numbers>

#include "elements/Bearing.hpp"
#include "elements/PlainJournalBearing.hpp"
#include "elements/PointInertia.hpp"
#include "fem/rotor/RotorCampbell.hpp"
#include "fem/rotor/RotorStability.hpp"
#include "tests/Helpers.hpp"
#include "tests/fem/rotor/RotorTestSupport.hpp"

using namespace beamrotor;
using namespace beamrotor::test;

namespace {

constexpr double kPiShort = std::numbers::pi;
constexpr double kRadPerRpmShort = kPiShort / 30;

/// A plain journal whose coefficients are the short-bearing ones at exactly the speed asked
/// (no table between speeds), so the refined onset is the model's own.
class ExactJournal : public SpeedDependentElement {
 public:
  ExactJournal(int node, PlainJournal journal, double restSpeed)
      : node_(node), journal_(journal), rest_(restSpeed) {}
  ElementDofs dofs() const override { return lateralDofs(node_); }
  ElementMatrix stiffnessAt(double speed) const override { return at(speed).stiffnessAt(0); }
  ElementMatrix dampingAt(double speed) const override { return at(speed).dampingAt(0); }
  std::string kind() const override { return "bearing"; }

 private:
  /// Below `rest_` (the film needs spin) the coefficients there: any finite baseline will do.
  Bearing at(double speed) const {
    return Bearing(node_, shortBearingCoefficients(journal_, std::max(speed, rest_)));
  }
  int node_;
  PlainJournal journal_;
  double rest_;
};

}  // namespace

TEST_SUITE("short bearing published") {
  TEST_CASE("Friswell et al. 2010, Example 5.5.1: the eight coefficients to their printed digits") {
    // D 100 mm, L 30 mm, c 0.1 mm, mu 0.1 Pa s, W 525 N, 1500 rev/min. Printed (book's x
    // horizontal, y along the load, rotation reversed against ours, so x_book = -z):
    //   K = [12.81 16.39; -25.06 8.815] MN/m,   C = [232.9 -81.92; -81.92 294.9] kN s/m.
    // Ours: kzz = kxx_book, kyy = kyy_book, kzy = -kxy_book, kyz = -kyx_book, likewise C.
    // Tolerance: half a unit of the last printed digit.
    const PlainJournal b{0.1, 0.03, 1e-4, 0.1, 525};
    const BearingCoefficients k = shortBearingCoefficients(b, 1500 * kRadPerRpmShort);
    CHECK(std::abs(k.kzz / 1e6 - 12.81) <= 0.005);
    CHECK(std::abs(-k.kzy / 1e6 - 16.39) <= 0.005);
    CHECK(std::abs(-k.kyz / 1e6 - -25.06) <= 0.005);
    CHECK(std::abs(k.kyy / 1e6 - 8.815) <= 0.0005);
    CHECK(std::abs(k.czz / 1e3 - 232.9) <= 0.05);
    CHECK(std::abs(-k.czy / 1e3 - -81.92) <= 0.005);
    CHECK(std::abs(-k.cyz / 1e3 - -81.92) <= 0.005);
    CHECK(std::abs(k.cyy / 1e3 - 294.9) <= 0.05);
    // Its eccentricity ratio, 0.2663 (the value ROSS's short-bearing tests use for this
    // bearing's operating point), to the printed digit.
    CHECK(std::abs(eccentricityRatio(b, 1500 * kRadPerRpmShort) - 0.2663) <= 0.00005);
  }

  TEST_CASE("stability chart: a rigid rotor in short bearings is stable above eps = 0.756") {
    // The short-bearing stability chart (critical mass parameter m c w^2 / W against the
    // eccentricity ratio) rises without bound at eps = 0.756, the widely quoted limit above
    // which a rigid rotor in plain short bearings cannot whip. The threshold mass k_eq / w^2 is
    // W / c times a function of eps alone, positive and finite below the limit and negative
    // above it; bisection on eps finds where it changes sign. Printed to 3 digits: asked
    // within 0.0005.
    const double c = 1e-4;
    const auto massAt = [&](double eps) {
      // Any bearing at the speed where its eccentricity is eps: S_s picks the speed.
      const PlainJournal b{0.1, 0.04, c, 0.02, 1000};
      const double speed = shortBearingSommerfeld(eps) / b.sommerfeld(1.0);
      return thresholdMass(shortBearingCoefficients(b, speed));
    };
    CHECK(massAt(0.3) > 0);
    CHECK(massAt(0.9) < 0);
    double lo = 0.3, hi = 0.9;
    for (int i = 0; i < 60; ++i) ((massAt((lo + hi) / 2) > 0) ? lo : hi) = (lo + hi) / 2;
    CHECK(std::abs(lo - 0.756) <= 0.0005);
  }

  TEST_CASE("oil whip of a rigid symmetric rotor: the eigensolver's onset against the threshold") {
    // A symmetric rigid rotor of 200 kg in two equal short bearings whips in its cylindrical
    // mode: each bearing carries half, m = 100 kg, W = m g, so the mode is a mass m on one
    // bearing. D 100 mm, L 40 mm, c 0.1 mm, mu 0.02 Pa s. The threshold: the speed where the
    // bearing's threshold mass (above) equals m, found by bisection on the speed (the
    // eccentricity follows from the Sommerfeld number). The rotor eigensolver's onset
    // (Campbell bracket, regula falsi on max Re(lambda) to 1e-10 of the speed) must agree to
    // round-off of both root finders (asked 1e-7), whirling at about half the speed (the
    // threshold's w / Omega at eps 0.21 is 0.511).
    const double m = 100, g = 9.81;
    const PlainJournal b{0.1, 0.04, 1e-4, 0.02, m * g};
    Model model;
    const int n = model.addNode(Eigen::Vector3d::Zero());
    model.add<PointInertia>(n, DofSet{Dof::uy, Dof::uz}, m);
    model.add<ExactJournal>(n, b, 100 * kRadPerRpmShort);

    double lo = 2000 * kRadPerRpmShort, hi = 20000 * kRadPerRpmShort;
    const auto margin = [&](double speed) {
      return thresholdMass(shortBearingCoefficients(b, speed)) - m;  // > 0: stable
    };
    REQUIRE(margin(lo) > 0);
    REQUIRE(margin(hi) < 0);
    for (int i = 0; i < 100; ++i) ((margin((lo + hi) / 2) > 0) ? lo : hi) = (lo + hi) / 2;
    const double threshold = (lo + hi) / 2;  // about 8000 rpm

    std::vector<double> speeds;
    for (int i = 0; i <= 10; ++i) speeds.push_back((2000 + 1800.0 * i) * kRadPerRpmShort);
    const RotorOptions options = rotorOptions(2);
    const CampbellResult campbell = solveCampbell(model, speeds, options);
    const auto onset = instabilityOnset(model, campbell, options);
    REQUIRE(onset.has_value());
    CHECK(relError(onset->speed, threshold) < 1e-7);
    CHECK(onset->whirl == Whirl::forward);
    const double ratio = onset->frequencyHz * 2 * kPiShort / onset->speed;
    CHECK(ratio > 0.45);
    CHECK(ratio < 0.55);
    // The published operating point: eps at the onset well below the 0.756 limit.
    CHECK(eccentricityRatio(b, onset->speed) < 0.756);
  }
}

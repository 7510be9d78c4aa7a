// Campbell lines that leave the modes a sweep solves (issue 42, defect B), against closed
// forms. A speed ladder: a 1 kg mass on a bearing that stiffens linearly with speed, its two
// planes (kzz = 1.2 kyy) rising from 10 and 10.95 Hz to 100 and 109.5 Hz, climbs past six
// masses on constant bearings (30 to 80 Hz). The masses share no dof, so each mode is one
// mass in one plane and every frequency is a closed form, the damped sqrt(k / m - (c / 2m)^2)
// / (2 pi) of one mass on one spring and damper. With two lines the sweep
// solves four candidates per speed: once the rising mass has passed two others (four modes
// nearer the shift than its own), its modes are no longer among them, and the lines used to
// jump onto a constant mass's mode (MAC 0). The sweep now re-sweeps such an interval densely
// with twice the candidates and keeps the line's own mode; where even those do not hold it,
// the jump is reported.
#include <doctest/doctest.h>

#include <cmath>
#include <complex>
#include <vector>

#include "elements/Bearing.hpp"
#include "elements/PointInertia.hpp"
#include "fem/rotor/RotorCampbell.hpp"
#include "fem/rotor/RotorStability.hpp"
#include "tests/Helpers.hpp"
#include "tests/fem/rotor/RotorTestSupport.hpp"

using namespace beamrotor;
using namespace beamrotor::test;

namespace {

struct SpeedLadder {
  double top = 1000;                                     // rad/s, end of the rising bearing's table
  double riseFrom = 10, riseTo = 100;                    // Hz of the rising mass's y plane
  std::vector<double> constant{30, 40, 50, 60, 70, 80};  // Hz of the other masses' y planes
  double c = 0.5;        // N s/m on every plane
  double crossing = 0;   // cross-coupled stiffness of the constant masses, in their k
  double zRatio = 1.2;   // kzz / kyy of the rising mass (and, uncoupled, of the others)

  static double stiffness(double hz) { return std::pow(2 * kPi * hz, 2); }  // of 1 kg
  /// Damped frequency (Hz) of 1 kg on stiffness k and the damper c.
  double damped(double k) const { return std::sqrt(k - c * c / 4) / (2 * kPi); }
  /// The rising mass's y stiffness at speed W: linear between the table's rows.
  double risingK(double W) const {
    return stiffness(riseFrom) + (stiffness(riseTo) - stiffness(riseFrom)) * W / top;
  }
  /// Damped frequency (Hz) of the rising mass's plane at speed W: y (ratio 1) or z (zRatio).
  double rising(double W, double ratio) const { return damped(ratio * risingK(W)); }

  void build(Model& model) const {
    const int r = model.addNode(Eigen::Vector3d::Zero());
    model.add<PointInertia>(r, DofSet{Dof::uy, Dof::uz}, 1.0);
    const auto planes = [&](double k, double ratio) {
      return BearingCoefficients{k, 0, 0, ratio * k, c, 0, 0, c};
    };
    model.add<Bearing>(r, std::vector<double>{0.0, top},
                       std::vector<BearingCoefficients>{planes(risingK(0), zRatio),
                                                        planes(risingK(top), zRatio)});
    for (std::size_t i = 0; i < constant.size(); ++i) {
      const int n = model.addNode(Eigen::Vector3d(double(i + 1), 0, 0));
      model.add<PointInertia>(n, DofSet{Dof::uy, Dof::uz}, 1.0);
      const double k = stiffness(constant[i]);
      // Cross-coupled masses are isotropic, so that the coupling drives a forward whirl.
      BearingCoefficients b = planes(k, crossing > 0 ? 1.0 : zRatio);
      b.kyz = crossing * k;
      b.kzy = -crossing * k;
      model.add<Bearing>(n, b);
    }
  }

  std::vector<double> speeds(int steps) const {
    std::vector<double> s;
    for (int i = 0; i <= steps; ++i) s.push_back(top * i / steps);
    return s;
  }
};

/// The eigensolver's round-off in a frequency (~1e-13 relative on these 28 states), with room.
constexpr double kRoundOff = 1e-10;

}  // namespace

TEST_SUITE("rotor campbell") {
  TEST_CASE("a line whose mode leaves the candidates keeps it through a denser local sweep") {
    const SpeedLadder ladder;
    Model model;
    ladder.build(model);
    const CampbellResult c = solveCampbell(model, ladder.speeds(10), rotorOptions(2));
    REQUIRE(c.lines.size() == 2);
    // At 100 rad/s the rising mass (33 Hz) has passed the 30 Hz mass, at 200 (45.6 Hz) the
    // 40 Hz one too: four modes nearer the shift, its own no longer among four candidates.
    REQUIRE(ladder.rising(200, 1) > ladder.constant[1]);
    for (std::size_t s = 0; s < c.speeds.size(); ++s) {
      CAPTURE(c.speeds[s]);
      CHECK(relError(c.lines[0][s].dampedFrequencyHz, ladder.rising(c.speeds[s], 1)) <
            kRoundOff);
      CHECK(relError(c.lines[1][s].dampedFrequencyHz, ladder.rising(c.speeds[s], ladder.zRatio)) <
            kRoundOff);
      CHECK(c.mac[0][s] > 0.99);
    }
    CHECK(c.localSweeps >= 1);
    CHECK(c.jumps.empty());
    CHECK_FALSE(c.untracked.has_value());
  }

  TEST_CASE("a line that passes more modes in one step than twice the candidates: reported") {
    // Three steps: by 333 rad/s the rising y plane (58.3 Hz) has six modes nearer the shift
    // (three masses' two planes: the local sweep's eight candidates still hold it), its z
    // plane (63.9 Hz) eight (four masses' y planes, three z planes and the rising y plane:
    // not held).
    const SpeedLadder ladder;
    Model model;
    ladder.build(model);
    const CampbellResult c = solveCampbell(model, ladder.speeds(3), rotorOptions(2));
    for (std::size_t s = 0; s < c.speeds.size(); ++s)
      CHECK(relError(c.lines[0][s].dampedFrequencyHz, ladder.rising(c.speeds[s], 1)) <
            kRoundOff);
    REQUIRE(c.jumps.size() == 1);
    const LineJump& j = c.jumps.front();
    CHECK(j.line == 1);
    CHECK(j.speed == 1);
    CHECK(j.mac < 0.5);
    // It lands on a constant mass's plane (the y plane of one of them: its closed form), off
    // the rising z plane's own frequency there.
    double nearest = 1;
    for (double hz : ladder.constant)
      nearest = std::min(nearest, relError(j.toHz, ladder.damped(SpeedLadder::stiffness(hz))));
    CHECK(nearest < kRoundOff);
    CHECK(relError(c.lines[1][1].dampedFrequencyHz, ladder.rising(c.speeds[1], ladder.zRatio)) >
          0.05);
    // Where it came from: the rising z plane at a speed of the local sweep before the jump.
    CHECK(j.fromHz > ladder.rising(0, ladder.zRatio));
    CHECK(j.fromHz < ladder.rising(c.speeds[1], ladder.zRatio));
  }

  TEST_CASE("a growing mode no line follows is reported, and an onset on a jump is flagged") {
    // The constant masses cross-coupled: m x'' + c x' + (k - i Q) x = 0 (x = y + i z) grows
    // in forward whirl once Q > c omega (Childs 1993, ch. 3), here Q = 0.1 k against
    // c omega = 0.5 omega. The lines start on the rising mass, stable; the 30 Hz mass grows
    // from the first speed, outside the lines. Its root, the closed form below.
    SpeedLadder ladder;
    ladder.crossing = 0.1;
    Model model;
    ladder.build(model);
    const RotorOptions options = rotorOptions(2);
    const CampbellResult c = solveCampbell(model, ladder.speeds(3), options);
    REQUIRE(c.untracked.has_value());
    CHECK(c.untracked->speed == 0);
    const double k = SpeedLadder::stiffness(ladder.constant[0]), q = ladder.crossing * k;
    const std::complex<double> root =
        (-ladder.c + std::sqrt(std::complex<double>(ladder.c * ladder.c - 4 * k, 4 * q))) / 2.0;
    REQUIRE(root.real() > 0);
    // The closed form's root to the eigensolver's round-off (~1e-13 of |lambda|, 1e-10 of
    // the decrement, a ratio of the parts).
    CHECK(relError(c.untracked->frequencyHz, root.imag() / (2 * kPi)) < 1e-10);
    CHECK(relError(c.untracked->logDecrement, -2 * kPi * root.real() / root.imag()) < 1e-9);
    CHECK(c.untracked->whirl == Whirl::forward);
    // The z line jumps onto a growing mass at the second speed; refined on the line it
    // follows, the growth never starts inside the interval: the onset settles on that sweep
    // speed, and says so.
    REQUIRE(c.jumps.size() == 1);
    const auto onset = instabilityOnset(model, c, options);
    REQUIRE(onset.has_value());
    CHECK(onset->atSweepSpeed);
    CHECK(relError(onset->speed, c.speeds[1]) < 1e-9);
  }
}
